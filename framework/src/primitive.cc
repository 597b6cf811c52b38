#include "vl/primitive.hh"

#include <limits>
#include <ostream>

namespace vl {

void primitive::read_with_surface(scene_reader& in, std::vector<scene_reader::property> properties) {
    const std::string who = type_name();
    surface& s = surface_;
    properties.insert(properties.end(), {
        {"color", [&] { s.clr = in.read_color("color of " + who); }},
        {"kdr", [&] { s.kdr = in.read_nonnegative("kdr (diffuse reflection) of " + who); }},
        {"ksr", [&] { s.ksr = in.read_nonnegative("ksr (specular reflection) of " + who); }},
        {"kdt", [&] { s.kdt = in.read_nonnegative("kdt (diffuse transmission) of " + who); }},
        {"kst", [&] { s.kst = in.read_nonnegative("kst (specular transmission) of " + who); }},
        {"n", [&] { s.n = in.read_nonnegative("n (specular exponent) of " + who); }},
        {"ior", [&] { s.ior = in.read_positive("ior (index of refraction) of " + who); }},
        {"zero_t", [&] { s.zero_t = in.read_number("zero_t of " + who); }},
    });
    in.read_block(who, properties);
}

void primitive::write_surface(std::ostream& out) const {
    const surface d;
    const surface& s = surface_;
    const auto old_precision = out.precision(std::numeric_limits<double>::max_digits10);
    if (s.clr != d.clr) out << " color (" << s.clr.r << ", " << s.clr.g << ", " << s.clr.b << ", " << s.clr.a << ')';
    if (s.kdr != d.kdr) out << " kdr " << s.kdr;
    if (s.ksr != d.ksr) out << " ksr " << s.ksr;
    if (s.kdt != d.kdt) out << " kdt " << s.kdt;
    if (s.kst != d.kst) out << " kst " << s.kst;
    if (s.n != d.n) out << " n " << s.n;
    if (s.ior != d.ior) out << " ior " << s.ior;
    if (s.zero_t != d.zero_t) out << " zero_t " << s.zero_t;
    out.precision(old_precision);
}

}  // namespace vl
