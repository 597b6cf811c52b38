#pragma once
/// \file
/// \brief Type names in scene files (`SPHERE`, `BVH`, ...) and the factories behind them.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "vl/camera.hh"
#include "vl/rt_base_objects.hh"
#include "vl/scene.hh"
#include "vl/tracer.hh"

namespace vl {

/// \brief Every piece a scene can name, and the factories behind the names: the
/// thesis's `get_type()`, without the if-else chain to edit.
///
/// Object types (`SPHERE`, `BVH`, ...), tracers (`flat`, `whitted`), pixel sample
/// patterns (`center`, `jittered`) and the camera. Each stage binds its pieces in its
/// `register_stage_NN(registry&)`; the framework binds its own (`LIST`, `flat`,
/// `normals`) in register_framework(). An object type name is 1 to 10 upper-case letters
/// A-Z, as in the thesis, so it can never be mistaken for a keyword or a number.
class registry {
public:
    /// Makes a new, default-constructed object; the scene reader then calls its read().
    using factory = std::function<std::unique_ptr<rtab_component>()>;

    /// Binds `name` to `make`. Throws vl::usage_error for a malformed or taken name.
    void add(std::string_view name, factory make);
    /// A new object of type `name`, or nullptr when the name is not bound.
    std::unique_ptr<rtab_component> create(std::string_view name) const;
    /// True when `name` is bound.
    bool contains(std::string_view name) const;
    /// Every bound name, sorted.
    std::vector<std::string> names() const;

    /// True when `name` is 1 to 10 upper-case letters.
    static bool valid_name(std::string_view name);

    /// Makes the camera for a scene's settings and an image of `width` x `height`.
    using camera_factory = std::function<std::unique_ptr<camera>(const camera_settings&, int width, int height)>;
    /// Makes a pixel sample pattern.
    using sampler_factory = std::function<std::unique_ptr<sampler>()>;
    /// Makes a tracer for a scene (which must outlive it).
    using tracer_factory = std::function<std::unique_ptr<tracer>(const scene&)>;

    /// Sets the camera (one per program; stage 01's pinhole camera).
    void set_camera(camera_factory make);
    /// Binds a sample pattern's name (`center`, `grid`, ...).
    void add_sampler(std::string_view name, sampler_factory make);
    /// Binds a tracer's name (`flat`, `whitted`, ...).
    void add_tracer(std::string_view name, tracer_factory make);

    /// The camera for `settings`; throws vl::usage_error when no camera is registered.
    std::unique_ptr<camera> make_camera(const camera_settings& settings, int width, int height) const;
    /// The sample pattern `name`; throws vl::usage_error when it is not registered.
    std::unique_ptr<sampler> make_sampler(std::string_view name) const;
    /// The tracer `name` for `s`; throws vl::usage_error when it is not registered.
    std::unique_ptr<tracer> make_tracer(std::string_view name, const scene& s) const;

    /// True when a camera is set.
    bool has_camera() const { return static_cast<bool>(camera_); }
    /// Every bound sample pattern's name, sorted.
    std::vector<std::string> sampler_names() const;
    /// Every bound tracer's name, sorted.
    std::vector<std::string> tracer_names() const;

private:
    std::map<std::string, factory, std::less<>> factories_;
    camera_factory camera_;
    std::map<std::string, sampler_factory, std::less<>> samplers_;
    std::map<std::string, tracer_factory, std::less<>> tracers_;
};

/// Binds the framework's own pieces: the `LIST` type (vl::object_list) and the `flat`,
/// `normals` and `sky` tracers.
void register_framework(registry& r);

}  // namespace vl
