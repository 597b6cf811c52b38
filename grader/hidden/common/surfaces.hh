#pragma once
/// \file
/// \brief Surfaces for the hidden scene-file tests: one whose every key needs all 17
/// digits, an object's surface as its getters give it, and a surface as scene text.

#include <array>
#include <string>
#include <utility>

#include "grading.hh"
#include "vl/primitive.hh"
#include "vl/rt_base_objects.hh"

namespace vl::grading {

/// A surface with every key set to a value that needs all 17 digits.
inline surface full_precision_surface(double zero_t) {
    surface s;
    s.clr = color(0.1 + 1e-13, 1.0 / 3, 2.0 / 3 + 1e-12, 1.0 / 7);
    s.kdr = 0.7 + 1e-14;
    s.ksr = 1.0 / 3;
    s.kdt = 1e-7 / 3;
    s.kst = 0.2 + 3e-15;
    s.n = 123456.789012345;
    s.ior = 1.5 + 1e-13;
    s.zero_t = zero_t;
    return s;
}

/// The surface getters of an object, as a vl::surface.
inline surface surface_of(const rtab_component& o) {
    surface s;
    s.clr = o.clr();
    s.kdr = o.kdr();
    s.ksr = o.ksr();
    s.kdt = o.kdt();
    s.kst = o.kst();
    s.n = o.n();
    s.ior = o.ior();
    s.zero_t = o.zero_t();
    return s;
}

/// The surface keys of `s` as scene text (every digit).
inline std::string surface_text(const surface& s) {
    return " color " + num(s.clr.r) + " " + num(s.clr.g) + " " + num(s.clr.b) + " " + num(s.clr.a) + " kdr " +
           num(s.kdr) + " ksr " + num(s.ksr) + " kdt " + num(s.kdt) + " kst " + num(s.kst) + " n " + num(s.n) +
           " ior " + num(s.ior) + " zero_t " + num(s.zero_t);
}

/// Each surface key of `got` beside the same key of `want`, by name ("color red", "kdr",
/// ...): what a test compares key by key.
inline std::array<std::pair<const char*, std::pair<double, double>>, 11> surface_keys(const surface& got,
                                                                                      const surface& want) {
    return {{
        {"color red", {got.clr.r, want.clr.r}},   {"color green", {got.clr.g, want.clr.g}},
        {"color blue", {got.clr.b, want.clr.b}},  {"color alpha", {got.clr.a, want.clr.a}},
        {"kdr", {got.kdr, want.kdr}},             {"ksr", {got.ksr, want.ksr}},
        {"kdt", {got.kdt, want.kdt}},             {"kst", {got.kst, want.kst}},
        {"n", {got.n, want.n}},                   {"ior", {got.ior, want.ior}},
        {"zero_t", {got.zero_t, want.zero_t}},
    }};
}

}  // namespace vl::grading
