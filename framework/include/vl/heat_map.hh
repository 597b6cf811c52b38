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

/// The heat map of a `width` x `height` image whose per-pixel costs are `tests` (index
/// `x + y * width`, bottom row first), with a colour scale along the right edge: a strip
/// from black (0 tests, bottom) to white (`max` tests, top). Returns the largest cost.
std::uint32_t draw_heat_map(std::span<const std::uint32_t> tests, int width, int height, vfb& out);

/// Width of the colour scale strip, in pixels.
inline constexpr int heat_scale_width = 24;
/// Width of the gap between the image and the scale strip, in pixels.
inline constexpr int heat_scale_gap = 4;

}  // namespace vl
