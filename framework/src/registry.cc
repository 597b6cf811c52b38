#include "vl/registry.hh"

#include <algorithm>

#include "vl/error.hh"
#include "vl/object_list.hh"

namespace vl {

namespace {

/// `: a, b, c`, or ` (it registers none)`: what a message about a missing name ends with.
std::string registered(const std::vector<std::string>& names) {
    if (names.empty()) return " (it registers none)";
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "; it registers: " : ", ") + n;
    return out;
}

}  // namespace

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

std::vector<std::string> registry::sampler_names() const {
    std::vector<std::string> out;
    for (const auto& [name, make] : samplers_) out.push_back(name);
    return out;
}

std::vector<std::string> registry::tracer_names() const {
    std::vector<std::string> out;
    for (const auto& [name, make] : tracers_) out.push_back(name);
    return out;
}

void registry::set_camera(camera_factory make) {
    if (!make) throw usage_error("registry: set_camera() was given no factory");
    camera_ = std::move(make);
}

void registry::add_sampler(std::string_view name, sampler_factory make) {
    if (!make) throw usage_error("registry: sampler '" + std::string(name) + "' was given no factory");
    if (!samplers_.emplace(name, std::move(make)).second)
        throw usage_error("registry: sampler '" + std::string(name) + "' is already registered");
}

void registry::add_tracer(std::string_view name, tracer_factory make) {
    if (!make) throw usage_error("registry: tracer '" + std::string(name) + "' was given no factory");
    if (!tracers_.emplace(name, std::move(make)).second)
        throw usage_error("registry: tracer '" + std::string(name) + "' is already registered");
}

std::unique_ptr<camera> registry::make_camera(const camera_settings& settings, int width, int height) const {
    if (!camera_)
        throw usage_error("no camera is registered in this build: the camera is a stage's piece, "
                          "set by that stage's registration function (registry::set_camera)");
    return camera_(settings, width, height);
}

std::unique_ptr<sampler> registry::make_sampler(std::string_view name) const {
    const auto it = samplers_.find(name);
    if (it == samplers_.end())
        throw usage_error("no sampler '" + std::string(name) + "' is registered in this build" +
                          registered(sampler_names()));
    return it->second();
}

std::unique_ptr<tracer> registry::make_tracer(std::string_view name, const scene& s) const {
    const auto it = tracers_.find(name);
    if (it == tracers_.end())
        throw usage_error("no tracer '" + std::string(name) + "' is registered in this build" +
                          registered(tracer_names()));
    return it->second(s);
}

void register_framework(registry& r) {
    r.add("LIST", [] { return std::make_unique<object_list>(); });
    r.add_tracer("flat", [](const scene& s) { return std::make_unique<flat_tracer>(s); });
    r.add_tracer("normals", [](const scene& s) { return std::make_unique<normals_tracer>(s); });
    r.add_tracer("sky", [](const scene& s) { return std::make_unique<sky_tracer>(s); });
}

}  // namespace vl
