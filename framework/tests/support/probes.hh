#pragma once
// Test doubles for the component tree. Students need not read this file.
#include <algorithm>
#include <memory>
#include <ostream>

#include "vl/camera.hh"
#include "vl/error.hh"
#include "vl/primitive.hh"
#include "vl/registry.hh"
#include "vl/rt_base_objects.hh"
#include "vl/scene_reader.hh"

namespace vl::test {

/// A leaf that reports a hit at a fixed distance (or a miss when t <= 0), whatever the ray.
class probe : public primitive {
public:
    explicit probe(double t = 0) : t_(t) {}
    std::string type_name() const override { return "PROBE"; }
    void read(scene_reader& in) override {
        read_with_surface(in, {{"t", [&] { t_ = in.read_nonnegative("t of PROBE"); }}});
    }
    void write(std::ostream& s) const override {
        s << "PROBE { t " << t_;
        write_surface(s);
        s << " }";
    }
    vector normal(const point&) const override { return {0, 0, 1}; }
    point min_point() const override { return {-1, -1, -1}; }
    point max_point() const override { return {t_, 1, 1}; }
    double t() const { return t_; }

private:
    intersection find_intersection(const ray&) const override {
        return t_ > zero_t() ? intersection::at(t_, this) : intersection::none();
    }
    double t_;
};

/// A composite with a bound that every ray enters: returns its nearest child hit, or
/// "entered me but hit nothing" (the thesis's rule for composites).
class bounded_probe_list : public rtab_composite {
public:
    std::string type_name() const override { return "BOUNDED"; }
    void read(scene_reader& in) override { in.read_children(*this); }

private:
    intersection find_intersection(const ray& r) const override {
        const intersection i = nearest_child_hit(r);
        return i.hit() ? i : intersection::composite_only(this);
    }
};

/// A composite that refuses a PROBE at t 10 or more (as a bounding volume refuses an
/// unbounded child): insert() throws vl::usage_error.
class near_probe_list : public rtab_composite {
public:
    std::string type_name() const override { return "NEARONLY"; }
    void read(scene_reader& in) override { in.read_children(*this); }
    void insert(std::unique_ptr<rtab_component> child) override {
        if (const auto* p = dynamic_cast<const probe*>(child.get()); p && p->t() >= 10)
            throw usage_error("NEARONLY cannot hold a PROBE at t 10 or more");
        rtab_composite::insert(std::move(child));
    }

private:
    intersection find_intersection(const ray& r) const override { return nearest_child_hit(r); }
};

/// A sample pattern that puts every sample at the centre of the pixel.
class probe_sampler : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t) const override {
        std::fill(out.begin(), out.end(), sample_offset{0.5, 0.5});
    }
};

/// The framework's pieces plus PROBE, BOUNDED and NEARONLY, and probe_sampler as the sample
/// patterns `center` and `jittered`, for reading test scenes.
inline registry probe_types() {
    registry r;
    register_framework(r);
    r.add("PROBE", [] { return std::make_unique<probe>(); });
    r.add("BOUNDED", [] { return std::make_unique<bounded_probe_list>(); });
    r.add("NEARONLY", [] { return std::make_unique<near_probe_list>(); });
    r.add_sampler("center", [] { return std::make_unique<probe_sampler>(); });
    r.add_sampler("jittered", [] { return std::make_unique<probe_sampler>(); });
    return r;
}

}  // namespace vl::test
