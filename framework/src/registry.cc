#include "vl/registry.hh"

#include <algorithm>

#include "vl/error.hh"
#include "vl/object_list.hh"

namespace vl {

bool registry::valid_name(std::string_view name) {
    return !name.empty() && name.size() <= 10 &&
           std::all_of(name.begin(), name.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
}

void registry::add(std::string_view name, factory make) {
    if (!valid_name(name))
        throw usage_error("registry: type name '" + std::string(name) +
                          "' must be 1 to 10 upper-case letters A-Z (like SPHERE)");
    if (!make) throw usage_error("registry: type name '" + std::string(name) + "' was given no factory");
    if (!factories_.emplace(name, std::move(make)).second)
        throw usage_error("registry: type name '" + std::string(name) + "' is already registered");
}

std::unique_ptr<rtab_component> registry::create(std::string_view name) const {
    const auto it = factories_.find(name);
    return it == factories_.end() ? nullptr : it->second();
}

bool registry::contains(std::string_view name) const { return factories_.find(name) != factories_.end(); }

std::vector<std::string> registry::names() const {
    std::vector<std::string> out;
    for (const auto& [name, make] : factories_) out.push_back(name);
    return out;
}

void register_framework(registry& r) {
    r.add("LIST", [] { return std::make_unique<object_list>(); });
}

}  // namespace vl
