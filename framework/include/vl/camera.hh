#pragma once
/// \file
/// \brief Cameras and pixel sample patterns: where primary rays come from.
///
/// These are interfaces; stage 01 implements them (the pinhole camera, the centre, grid,
/// jittered and random patterns) and binds them in its registration function.

#include <cstdint>
#include <span>

#include "vl/ray.hh"

namespace vl {

/// \brief Turns a position on the image into the ray that sees it.
class camera {
public:
    virtual ~camera() = default;
    /// The primary ray through image position (`x`, `y`), in pixel units: pixel (i, j)
    /// covers [i, i + 1) x [j, j + 1), and (0, 0) is the LOWER-LEFT corner of the image,
    /// as in the vfb. The centre of pixel (i, j) is (i + 0.5, j + 0.5).
    virtual ray primary_ray(double x, double y) const = 0;
};

/// \brief Where inside a pixel its rays go.
struct sample_offset {
    double dx = 0.5;  ///< from the pixel's left edge, in [0, 1)
    double dy = 0.5;  ///< from the pixel's bottom edge, in [0, 1)
};

/// \brief A pixel sample pattern: n offsets for one pixel.
class sampler {
public:
    virtual ~sampler() = default;
    /// Fills `out` (its size is the number of samples wanted) with offsets in [0, 1)^2.
    /// `seed` is fixed per pixel by the render driver, so a pattern that uses random
    /// numbers gives the same offsets for the same pixel on every run and thread count.
    virtual void offsets(std::span<sample_offset> out, std::uint64_t seed) const = 0;
};

}  // namespace vl
