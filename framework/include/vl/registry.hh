#pragma once
/// \file
/// \brief Type names in scene files (`SPHERE`, `BVH`, ...) and the factories behind them.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "vl/rt_base_objects.hh"

namespace vl {

/// \brief Maps a scene file's type names to factories: the thesis's `get_type()`,
/// without the if-else chain to edit.
///
/// Each stage binds its names in its `register_stage_NN(registry&)`; the framework binds
/// its own (`LIST`) in register_framework(). A name is 1 to 10 upper-case letters A-Z,
/// as in the thesis, so it can never be mistaken for a keyword or a number.
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

private:
    std::map<std::string, factory, std::less<>> factories_;
};

/// Binds the framework's own types: `LIST` (vl::object_list).
void register_framework(registry& r);

}  // namespace vl
