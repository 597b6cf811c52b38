#pragma once
/// \file
/// \brief The intersection heat map: what each pixel cost, as the thesis's colour printouts.
#include <cstdint>
#include <span>

#include "vl/vfb.hh"

namespace vl {

/// A colour for `fraction` in [0, 1] of the largest cost: black, through red and yellow,
/// to white (a "black-body" ramp: brightness grows steadily, so it also reads in gray).
color heat_color(double fraction);

/// Where `count` tests fall on the heat map's scale from 0 (0 tests) to 1 (`most` tests):
/// count / most, or with `log_scale` log(1 + count) / log(1 + most), which spreads the
/// many cheap pixels apart when a few pixels cost far more. 0 when `most` is 0; counts
/// above `most` give 1.
double heat_fraction(std::uint32_t count, std::uint32_t most, bool log_scale);

/// The inverse of heat_fraction: the count at `fraction` (clamped to [0, 1]) of the scale,
/// rounded to the nearest whole test. For the legend's tick labels.
std::uint32_t heat_count(double fraction, std::uint32_t most, bool log_scale);

/// The heat map of a `width` x `height` image whose per-pixel costs are `tests` (index
/// `x + y * width`, bottom row first), with a colour scale along the right edge: a strip
/// from black (0 tests, bottom) to white (`max` tests, top), linear or, with `log_scale`,
/// logarithmic (heat_fraction). Returns the largest cost.
std::uint32_t draw_heat_map(std::span<const std::uint32_t> tests, int width, int height, vfb& out,
                            bool log_scale = false);

/// Width of the colour scale strip, in pixels.
inline constexpr int heat_scale_width = 24;
/// Width of the gap between the image and the scale strip, in pixels.
inline constexpr int heat_scale_gap = 4;

}  // namespace vl
