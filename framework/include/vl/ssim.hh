#pragma once
/// \file
/// \brief SSIM, the structural similarity index of Wang, Bovik, Sheikh and Simoncelli,
/// "Image Quality Assessment: From Error Visibility to Structural Similarity", IEEE
/// Transactions on Image Processing 13(4), 2004.
///
/// SSIM compares the local mean (luminance), standard deviation (contrast) and correlation
/// (structure) of two images in a sliding window. It is 1 for identical images and falls
/// towards 0 (it can go below) as they differ; unlike FLIP it ignores colour. The choices
/// here are those of the paper's Section III-C and its published MATLAB code
/// (ssim_index.m): an 11 x 11 circular-symmetric Gaussian window with standard deviation
/// 1.5 pixels, normalised to sum 1; K1 = 0.01, K2 = 0.03; dynamic range L = 1; and only
/// windows that lie wholly inside the image (the code's `'valid'` filtering). An image
/// narrower or lower than 11 pixels has no such window: there every pixel's window repeats
/// the edge pixels instead (clamp to edge). No downsampling is done first.
///
/// The signal is the **luminance**: each pixel's relative luminance (vl::luminance of its
/// linear RGB, clamped to [0, 1]) encoded back with the sRGB transfer function, i.e. the
/// gray value a gray 8-bit file of the image holds, in [0, 1]. Alpha is dropped.
#include <vector>

#include "vl/image.hh"

namespace vl {

/// \brief The constants of SSIM as the paper sets them.
namespace ssim_constants {
inline constexpr int window = 11;       ///< window width and height in pixels
inline constexpr double sigma = 1.5;    ///< standard deviation of the Gaussian window
inline constexpr double k1 = 0.01;      ///< C1 = (K1 L)^2 keeps the luminance term stable
inline constexpr double k2 = 0.03;      ///< C2 = (K2 L)^2 keeps the contrast-structure term stable
inline constexpr double range = 1.0;    ///< L, the dynamic range of the signal
}  // namespace ssim_constants

/// \brief The local SSIM of every window and their mean.
struct ssim_result {
    int width = 0;           ///< windows per row of `map`
    int height = 0;          ///< rows of `map`
    std::vector<float> map;  ///< SSIM of each window, rows top to bottom
    double mean = 1;         ///< the mean SSIM (MSSIM in the paper): what is reported
};

/// \brief SSIM of `test` against `reference` (symmetric in the two).
///
/// Both must have the same width and height (else vl::usage_error saying both sizes).
/// `map` is (width - 10) x (height - 10) for images of at least 11 x 11, else the images' size.
ssim_result ssim(const image& reference, const image& test);

}  // namespace vl
