#pragma once
/// \file
/// \brief LDR-FLIP: how different two images look to a person flipping between them.
///
/// FLIP is the image difference evaluator of Andersson, Nilsson, Akenine-Möller, Oskarsson,
/// Åström and Fairchild, "FLIP: A Difference Evaluator for Alternating Images" (Proc. ACM
/// Comput. Graph. Interact. Tech. 3(2), HPG 2020). It gives every pixel an error in [0, 1]:
/// 0 where the two images cannot be told apart at the given viewing distance, 1 for the
/// largest difference a display can show (green against blue). This is the paper's LDR
/// version, for images whose colours are in [0, 1]; docs/image-metrics.md walks through
/// every step with its constants.
///
/// The two halves of the algorithm, as the paper names them:
///
/// - **colour pipeline**: both images are filtered with contrast sensitivity functions
///   (what detail the eye resolves at `pixels_per_degree`), compared in a perceptually
///   uniform colour space (CIELab with the Hunt adjustment, distance HyAB) and the
///   distance is mapped to [0, 1] so that small differences spread over most of the range;
/// - **feature pipeline**: edges and points (first and second derivatives of a Gaussian)
///   are detected in each image's unfiltered luminance; where they differ the colour error
///   is raised (its exponent lowered), since the eye notices a lost or added edge at once.
///
/// Inputs are vl::image of any channel count and sample type: integer samples are sRGB
/// (linearised first), float samples linear; gray is spread to RGB, alpha is dropped.
/// Image borders repeat the edge pixel (clamp to edge), as the published C++ tool does.
#include <cstddef>
#include <span>
#include <vector>

#include "vl/image.hh"

namespace vl {

/// \brief The constants of LDR-FLIP, named as in the paper.
///
/// The values are the paper's, and those of the published implementation (NVlabs/flip on
/// GitHub), which docs/image-metrics.md lists with where each comes from.
namespace flip_constants {
inline constexpr double qc = 0.7;   ///< exponent applied to the HyAB colour distance
inline constexpr double pc = 0.4;   ///< fraction of the largest distance that is "small"...
inline constexpr double pt = 0.95;  ///< ...and the part of [0, 1] the small distances get
inline constexpr double gw = 0.082; ///< feature detectors: peak-to-trough width in degrees
inline constexpr double qf = 0.5;   ///< exponent applied to the feature difference
}  // namespace flip_constants

/// The paper's viewing conditions: a 0.7 m wide 3840-pixel monitor seen from 0.7 m, which
/// is 3840 * pi / 180 ~ 67.02 pixels per degree of visual angle.
double flip_default_pixels_per_degree();

/// Pixels per degree for a monitor `monitor_width` metres wide showing `resolution_x`
/// pixels across, seen from `distance` metres (the paper's formula).
double flip_pixels_per_degree(double distance, double resolution_x, double monitor_width);

/// \brief What FLIP needs to know about how the images are seen.
struct flip_options {
    /// Pixels per degree of visual angle: more pixels per degree (farther away, or a finer
    /// display) means finer detail is invisible and is filtered away.
    double pixels_per_degree = flip_default_pixels_per_degree();
};

/// \brief The FLIP error of every pixel, and what it pools to.
struct flip_result {
    int width = 0;             ///< pixels per row, as the inputs
    int height = 0;            ///< rows, as the inputs
    std::vector<float> error;  ///< per pixel, rows top to bottom, each in [0, 1]
    double mean = 0;           ///< the mean error: the single number the FLIP authors now recommend
    double max = 0;            ///< the largest pixel error
    double weighted_median = 0;      ///< weighted_percentile(error, 0.50)
    double weighted_quartile_1 = 0;  ///< weighted_percentile(error, 0.25)
    double weighted_quartile_3 = 0;  ///< weighted_percentile(error, 0.75)
};

/// \brief LDR-FLIP of `test` against `reference`.
///
/// Both must have the same width and height (else vl::usage_error saying both
/// sizes); channels and sample types may differ. Colours outside [0, 1] (float images) are
/// clamped first, since LDR-FLIP is defined for displayable colours only.
flip_result flip(const image& reference, const image& test, const flip_options& options = {});

/// \brief The weighted percentile the FLIP tool reports ("weighted median" for p = 0.5).
///
/// Each value is weighted by itself, so large errors count more: the result is the smallest
/// value v of the sorted values such that the values up to and including v sum to more
/// than p times the sum of all values. 0 when every value is 0 (or there are none).
double flip_weighted_percentile(std::span<const float> values, double p);

/// \brief The error map as an 8-bit sRGB RGB image of the inputs' size, coloured with the
/// magma colour map (black-purple for 0 through orange to pale yellow for 1), as the paper
/// and the FLIP tool show it. Entry round(255 * error) of the 256-entry map is used.
image flip_error_map(const flip_result& result);

/// The magma colour of `error` (clamped to [0, 1]), as sRGB values in [0, 1].
void flip_magma(double error, double rgb[3]);

}  // namespace vl
