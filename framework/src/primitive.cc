#include "vl/primitive.hh"

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <mutex>
#include <ostream>
#include <set>

#include "full_precision.hh"

namespace vl {

void add_surface_properties(std::vector<scene_reader::property>& properties, scene_reader& in, surface& s,
                            const std::string& who) {
    properties.insert(properties.end(), {
        {"color", [&in, &s, who] { s.clr = in.read_color("color of " + who); }},
        {"kdr", [&in, &s, who] { s.kdr = in.read_nonnegative("kdr (diffuse reflection) of " + who); }},
        {"ksr", [&in, &s, who] { s.ksr = in.read_nonnegative("ksr (specular reflection) of " + who); }},
        {"kdt", [&in, &s, who] { s.kdt = in.read_nonnegative("kdt (diffuse transmission) of " + who); }},
        {"kst", [&in, &s, who] { s.kst = in.read_nonnegative("kst (specular transmission) of " + who); }},
        {"n", [&in, &s, who] { s.n = in.read_nonnegative("n (specular exponent) of " + who); }},
        {"ior", [&in, &s, who] { s.ior = in.read_positive("ior (index of refraction) of " + who); }},
        {"zero_t", [&in, &s, who] { s.zero_t = in.read_number("zero_t of " + who); }},
    });
}

void write_surface(std::ostream& out, const surface& s) {
    const surface d;
    const detail::full_precision digits(out);
    if (s.clr != d.clr) out << " color (" << s.clr.r << ", " << s.clr.g << ", " << s.clr.b << ", " << s.clr.a << ')';
    if (s.kdr != d.kdr) out << " kdr " << s.kdr;
    if (s.ksr != d.ksr) out << " ksr " << s.ksr;
    if (s.kdt != d.kdt) out << " kdt " << s.kdt;
    if (s.kst != d.kst) out << " kst " << s.kst;
    if (s.n != d.n) out << " n " << s.n;
    if (s.ior != d.ior) out << " ior " << s.ior;
    if (s.zero_t != d.zero_t) out << " zero_t " << s.zero_t;
}

void primitive::read_with_surface(scene_reader& in, std::vector<scene_reader::property> properties) {
    const std::string who = type_name();
    surface s = *surface_;
    add_surface_properties(properties, in, s, who);
    in.read_block(who, properties);
    set_surface(s);
}

void primitive::write_surface(std::ostream& out) const { vl::write_surface(out, *surface_); }

namespace {

/// A surface's values as bits, so that equal means identical (NaN and -0 included) and
/// the order is a strict weak one, which doubles with NaN do not give.
std::array<std::uint64_t, 11> bits_of(const surface& s) {
    const double v[11] = {s.clr.r, s.clr.g, s.clr.b, s.clr.a, s.kdr, s.ksr, s.kdt, s.kst, s.n, s.ior, s.zero_t};
    std::array<std::uint64_t, 11> b{};
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = std::bit_cast<std::uint64_t>(v[i]);
    return b;
}

struct bitwise_less {
    bool operator()(const surface& a, const surface& b) const { return bits_of(a) < bits_of(b); }
};

}  // namespace

const surface* primitive::shared_surface(const surface& s) {
    static std::mutex mutex;
    static std::set<surface, bitwise_less> surfaces;  // a set's elements never move
    const std::lock_guard lock(mutex);
    return &*surfaces.insert(s).first;
}

const surface* primitive::default_surface() {
    static const surface* const defaults = shared_surface(surface{});
    return defaults;
}

}  // namespace vl
