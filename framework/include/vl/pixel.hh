#pragma once
/// \file
/// \brief Pixels for the virtual frame buffer: vl::vfb_pixel and the pixel storages.
///
/// The thesis (User's Manual, "pixel", "STORAGE_CLASS", "vfb_pixel") separates two ideas:
///
/// - **what the client means** by a pixel: black or white, a gray, an RGB colour, a colour
///   with a depth or an alpha, one sample of an antialiased pixel. That is vl::vfb_pixel,
///   whose constructors are the thesis's;
/// - **how the buffer stores it**: a *storage*. Switching storage changes memory and
///   precision, never the client code. A storage given a richer pixel than it holds
///   approximates it (gray storage keeps the luminance of an RGB pixel, a storage without
///   sub-pixels keeps the last sample, ...); it never refuses one.
///
/// The thesis chose the storage with `typedef ... STORAGE_CLASS` and made `vfb_pixel`
/// inherit from it. Here a storage is a *policy type*: a struct naming its `cell` (what one
/// pixel occupies in memory) and three static functions, `store`, `load` and `clear`.
/// vl::storage_class is the one line that picks the default, and vl::vfb can also be given
/// any storage by template argument or, from a scene file, by name (see vfb.hh).
///
/// Every storage follows the thesis's rule for `operator=`: a z-buffered cell takes a write
/// only when the new `az` is greater than or equal to the stored one.

#include "vl/tuples.hh"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

namespace vl {

/// \name Colour encoding
/// The renderer computes **linear** light; 8-bit files (and the 8-bit storages) hold
/// **sRGB-encoded** values, because 256 linear levels show visible bands in the darks.
/// These functions are the only place the framework converts between the two: the sRGB
/// transfer function of IEC 61966-2-1:1999 (a straight segment near black, then a 2.4
/// power). PFM files and float storages stay linear.
///@{

/// Linear light in [0, 1] to its sRGB encoding in [0, 1] (values outside are clamped).
double linear_to_srgb(double linear);
/// sRGB encoding in [0, 1] to linear light in [0, 1] (values outside are clamped).
double srgb_to_linear(double encoded);
/// Linear light to the nearest 8-bit sRGB code, exactly `round(255 * linear_to_srgb(x))`,
/// found in a table of the 255 decision points (no `pow` per pixel): a 4096-piece index
/// of the unit interval says where to start, and a step or two finds the code.
std::uint8_t linear_to_srgb8(double linear);
/// An 8-bit sRGB code to linear light, from a 256-entry table.
float srgb8_to_linear(std::uint8_t code);
/// Relative luminance of a linear RGB colour: Y = 0.2126 R + 0.7152 G + 0.0722 B, the
/// weights of the sRGB (ITU-R BT.709) primaries. The thesis averaged (r + g + b) / 3; the
/// eye is far more sensitive to green, and luminance is what a gray print shows.
constexpr double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
///@}

/// \brief One pixel as the client means it: a colour, an `az` value, and optionally where in
/// the virtual plane it was sampled.
///
/// `az` is the thesis's "alpha or z": a z-buffered storage compares it (larger wins, so
/// use e.g. minus the distance), an alpha storage keeps it as opacity, the others ignore
/// it. `-infinity` means "none", as in the thesis.
///
/// A pixel built from **double** coordinates is one *sample*: an antialiased storage puts it
/// into the sub-pixel that the fractional part of (x, y) falls in. A pixel built from
/// **int** coordinates, or without coordinates, covers the whole pixel (every sub-pixel).
/// Virtual pixel (i, j) covers [i, i + 1) x [j, j + 1), with (0, 0) at the lower left.
///
/// Colours are linear and usually in [0, 1]; storages with fewer bits clamp.
class vfb_pixel {
public:
    /// The thesis's "no alpha or z value".
    static constexpr double no_az = -std::numeric_limits<double>::infinity();

    /// Black, no az: what vl::vfb::clear leaves.
    constexpr vfb_pixel() = default;
    /// Black (0) or white (any other value).
    constexpr explicit vfb_pixel(int black_or_white) : vfb_pixel(black_or_white != 0 ? 1.0 : 0.0) {}
    /// A shade of gray between black (0) and white (1).
    constexpr explicit vfb_pixel(double gray) : r_(gray), g_(gray), b_(gray) {}
    /// An RGB colour.
    constexpr vfb_pixel(double r, double g, double b) : r_(r), g_(g), b_(b) {}
    /// An RGB colour with an alpha or z value.
    constexpr vfb_pixel(double az, double r, double g, double b) : az_(az), r_(r), g_(g), b_(b) {}
    /// A whole pixel at (x, y): every sub-pixel of an antialiased storage gets the colour.
    constexpr vfb_pixel(int x, int y, double az, double r, double g, double b)
        : az_(az), r_(r), g_(g), b_(b), x_(x), y_(y), has_position_(true) {}
    /// One sample at (x, y): an antialiased storage sets only the sub-pixel (x, y) is in.
    constexpr vfb_pixel(double x, double y, double az, double r, double g, double b)
        : az_(az), r_(r), g_(g), b_(b), x_(x), y_(y), has_position_(true), is_sample_(true) {}
    /// One sample at (p.x, p.y) with az = p.z (the depth of the hit), coloured c.
    constexpr vfb_pixel(const point& p, const color& c)
        : vfb_pixel(p.x, p.y, p.z, c.r, c.g, c.b) {}
    /// A whole pixel of colour c (c.a is not used), no az.
    constexpr explicit vfb_pixel(const color& c) : vfb_pixel(c.r, c.g, c.b) {}

    constexpr double az() const { return az_; }   ///< Alpha or z; -infinity when none.
    constexpr double r() const { return r_; }     ///< Red, linear.
    constexpr double g() const { return g_; }     ///< Green, linear.
    constexpr double b() const { return b_; }     ///< Blue, linear.
    /// The colour as a vl::color (alpha channel 0, the framework's convention).
    constexpr color clr() const { return {r_, g_, b_, 0}; }
    /// Relative luminance (see vl::luminance).
    constexpr double gray() const { return luminance(r_, g_, b_); }

    /// True if the pixel was built with coordinates.
    constexpr bool has_position() const { return has_position_; }
    /// True if the pixel is one sample (double coordinates), false for a whole pixel.
    constexpr bool is_sample() const { return is_sample_; }
    constexpr double x() const { return x_; }  ///< Virtual x coordinate (0 if none).
    constexpr double y() const { return y_; }  ///< Virtual y coordinate (0 if none).
    /// Where in its pixel a sample lies, each in [0, 1): the fractional parts of x and y.
    double sub_x() const { return x_ - std::floor(x_); }
    /// See sub_x().
    double sub_y() const { return y_ - std::floor(y_); }

    /// Same colour and az (positions are where a pixel was made, not what it is).
    friend constexpr bool operator==(const vfb_pixel& p, const vfb_pixel& q) {
        return p.az_ == q.az_ && p.r_ == q.r_ && p.g_ == q.g_ && p.b_ == q.b_;
    }

private:
    double az_ = no_az;
    double r_ = 0, g_ = 0, b_ = 0;
    double x_ = 0, y_ = 0;
    bool has_position_ = false;
    bool is_sample_ = false;
};

/// \brief Black or white, one bit logically (one byte in memory, so that every pixel stays
/// addressable; PBM files pack eight to a byte).
///
/// Approximation: white when the pixel's luminance encodes to sRGB 0.5 or more, the same
/// threshold a PBM writer uses on an 8-bit gray. az is dropped.
struct bw_storage {
    /// \brief One black-or-white pixel.
    struct cell { std::uint8_t white = 0; /**< 0 black, 1 white */ };
    static constexpr std::string_view name = "bw";                ///< Name in scene files.
    static constexpr std::size_t bytes_per_pixel = sizeof(cell);  ///< Memory per pixel.
    static constexpr int natural_channels = 1;                    ///< Gray, in files.
    /// Keeps white or black.
    static void store(cell& c, const vfb_pixel& p) { c.white = linear_to_srgb8(p.gray()) >= 128 ? 1 : 0; }
    /// The stored pixel as 0 or 1.
    static vfb_pixel load(const cell& c) { return vfb_pixel(static_cast<int>(c.white)); }
    /// Black.
    static void clear(cell& c) { c = {}; }
};

/// \brief 256 shades of gray, sRGB-encoded (1 byte per pixel).
///
/// Approximation: an RGB pixel keeps its luminance; az is dropped.
struct gray8_storage {
    /// \brief One gray pixel, sRGB-encoded.
    struct cell { std::uint8_t gray = 0; /**< sRGB code */ };
    static constexpr std::string_view name = "gray8";             ///< Name in scene files.
    static constexpr std::size_t bytes_per_pixel = sizeof(cell);  ///< Memory per pixel.
    static constexpr int natural_channels = 1;                    ///< Gray, in files.
    static constexpr int srgb8_channels = 1;  ///< A cell is exactly one 8-bit gray sample.
    /// Keeps the luminance.
    static void store(cell& c, const vfb_pixel& p) { c.gray = linear_to_srgb8(p.gray()); }
    /// The stored gray, linear.
    static vfb_pixel load(const cell& c) { return vfb_pixel(static_cast<double>(srgb8_to_linear(c.gray))); }
    /// Black.
    static void clear(cell& c) { c = {}; }
};

/// \brief 8-bit RGB, sRGB-encoded, as a PPM or PNG holds it (3 bytes per pixel): the default.
///
/// Approximation: channels are clamped to [0, 1] and rounded to 8 bits; az is dropped.
struct rgb8_storage {
    /// \brief One pixel as three sRGB bytes (no padding: a row is a PPM row).
    struct cell {
        std::uint8_t r = 0;  ///< red, sRGB code
        std::uint8_t g = 0;  ///< green, sRGB code
        std::uint8_t b = 0;  ///< blue, sRGB code
    };
    static constexpr std::string_view name = "rgb8";              ///< Name in scene files.
    static constexpr std::size_t bytes_per_pixel = sizeof(cell);  ///< Memory per pixel.
    static constexpr int natural_channels = 3;                    ///< RGB, in files.
    static constexpr int srgb8_channels = 3;  ///< A cell is exactly three 8-bit samples.
    /// Keeps the colour to 8 bits.
    static void store(cell& c, const vfb_pixel& p) {
        c = {linear_to_srgb8(p.r()), linear_to_srgb8(p.g()), linear_to_srgb8(p.b())};
    }
    /// The stored colour, linear.
    static vfb_pixel load(const cell& c) { return {srgb8_to_linear(c.r), srgb8_to_linear(c.g), srgb8_to_linear(c.b)}; }
    /// Black.
    static void clear(cell& c) { c = {}; }
};

/// \brief Linear float RGB (12 bytes per pixel): keeps HDR values for PFM files.
///
/// Approximation: az is dropped; float keeps about 7 significant digits.
struct rgb_float_storage {
    /// \brief One pixel as three linear floats.
    struct cell {
        float r = 0;  ///< red, linear
        float g = 0;  ///< green, linear
        float b = 0;  ///< blue, linear
    };
    static constexpr std::string_view name = "rgbf";              ///< Name in scene files.
    static constexpr std::size_t bytes_per_pixel = sizeof(cell);  ///< Memory per pixel.
    static constexpr int natural_channels = 3;                    ///< RGB, in files.
    /// Keeps the colour.
    static void store(cell& c, const vfb_pixel& p) {
        c = {static_cast<float>(p.r()), static_cast<float>(p.g()), static_cast<float>(p.b())};
    }
    /// The stored colour.
    static vfb_pixel load(const cell& c) { return {c.r, c.g, c.b}; }
    /// Black.
    static void clear(cell& c) { c = {}; }
};

/// \brief Z-buffered float RGB (16 bytes per pixel): the thesis's z rule.
///
/// A write lands only if its az is greater than or equal to the stored az (thesis,
/// "STORAGE_CLASS", `operator=`), so the nearest surface wins whatever the order of
/// writes. Cleared cells hold az = -infinity, so the first write always lands, even one
/// without az.
struct zbuffer_storage {
    /// \brief One pixel: depth and linear colour.
    struct cell {
        float z = -std::numeric_limits<float>::infinity();  ///< az of the pixel that landed
        float r = 0;  ///< red, linear
        float g = 0;  ///< green, linear
        float b = 0;  ///< blue, linear
    };
    static constexpr std::string_view name = "zrgb";              ///< Name in scene files.
    static constexpr std::size_t bytes_per_pixel = sizeof(cell);  ///< Memory per pixel.
    static constexpr int natural_channels = 3;                    ///< RGB, in files.
    /// Keeps the pixel if it is at least as near as the stored one.
    static void store(cell& c, const vfb_pixel& p) {
        const auto z = static_cast<float>(p.az());
        if (z >= c.z)
            c = {z, static_cast<float>(p.r()), static_cast<float>(p.g()), static_cast<float>(p.b())};
    }
    /// The stored colour and z.
    static vfb_pixel load(const cell& c) { return {c.z, c.r, c.g, c.b}; }
    /// Black at -infinity.
    static void clear(cell& c) { c = {}; }
};

/// \brief Float RGB plus alpha (16 bytes per pixel): az is the opacity, saved as a PNG's
/// alpha channel.
///
/// Every write lands (alpha is not a depth). Cleared cells are transparent black.
struct rgba_storage {
    /// \brief One pixel: linear colour and alpha.
    struct cell {
        float r = 0;  ///< red, linear
        float g = 0;  ///< green, linear
        float b = 0;  ///< blue, linear
        float a = 0;  ///< alpha: 0 transparent, 1 opaque
    };
    static constexpr std::string_view name = "rgba";              ///< Name in scene files.
    static constexpr std::size_t bytes_per_pixel = sizeof(cell);  ///< Memory per pixel.
    static constexpr int natural_channels = 4;                    ///< RGBA, in files.
    static constexpr bool has_alpha = true;                       ///< az is alpha here.
    /// Keeps colour and alpha; a pixel without az is opaque.
    static void store(cell& c, const vfb_pixel& p) {
        const double alpha = p.az() == vfb_pixel::no_az ? 1.0 : p.az();
        c = {static_cast<float>(p.r()), static_cast<float>(p.g()), static_cast<float>(p.b()),
             static_cast<float>(alpha)};
    }
    /// The stored colour, alpha as az.
    static vfb_pixel load(const cell& c) { return {c.a, c.r, c.g, c.b}; }
    /// Transparent black.
    static void clear(cell& c) { c = {}; }
};

/// \brief N x N sub-pixels per pixel, each kept by the storage Sub (z-buffered float RGB
/// unless told otherwise), averaged on read: a box filter (N*N*Sub bytes per pixel).
///
/// A sample (a pixel built from double coordinates) lands in the sub-pixel its fractional
/// position falls in, with Sub's rule (so each sub-pixel is z-buffered separately, as the
/// thesis asks). A whole pixel (int or no coordinates) goes to every sub-pixel. Reading
/// averages the colours of all sub-pixels and the az of those that have one (the thesis
/// chose the average too). Memory grows with N*N: switch to a storage without sub-pixels
/// when memory is short, and client code does not change.
template <int N, class Sub = zbuffer_storage>
struct antialiased_storage {
    static_assert(N >= 1 && N <= 8, "antialiased_storage: N must be between 1 and 8");
    /// \brief One pixel: N*N sub-pixels, row by row from the bottom.
    struct cell { typename Sub::cell sub[N * N]; /**< sub-pixel (i, j) is sub[j * N + i] */ };
    /// Name in scene files: "aa" followed by N, e.g. "aa4".
    static constexpr std::string_view name = std::string_view("aa1aa2aa3aa4aa5aa6aa7aa8").substr(3 * (N - 1), 3);
    static constexpr std::size_t bytes_per_pixel = sizeof(cell);  ///< Memory per pixel.
    static constexpr int natural_channels = Sub::natural_channels;  ///< As Sub.
    static constexpr int size = N;  ///< Sub-pixels along each axis.

    /// Stores a sample in its sub-pixel, or a whole pixel in all of them.
    static void store(cell& c, const vfb_pixel& p) {
        if (!p.is_sample()) {
            for (auto& s : c.sub) Sub::store(s, p);
            return;
        }
        // min() guards against sub_x() rounding up to exactly 1.0 for x just below an integer.
        const int i = std::min(N - 1, static_cast<int>(p.sub_x() * N));
        const int j = std::min(N - 1, static_cast<int>(p.sub_y() * N));
        Sub::store(c.sub[j * N + i], p);
    }
    /// The average of the sub-pixels.
    static vfb_pixel load(const cell& c) {
        double r = 0, g = 0, b = 0, az = 0;
        int with_az = 0;
        for (const auto& s : c.sub) {
            const vfb_pixel p = Sub::load(s);
            r += p.r(); g += p.g(); b += p.b();
            if (std::isfinite(p.az())) { az += p.az(); ++with_az; }
        }
        constexpr double n = N * N;
        return {with_az > 0 ? az / with_az : vfb_pixel::no_az, r / n, g / n, b / n};
    }
    /// Clears every sub-pixel.
    static void clear(cell& c) { for (auto& s : c.sub) Sub::clear(s); }
};

/// The thesis's `STORAGE_CLASS`: the storage a vl::vfb uses when none is named. Change
/// this one line to change every default frame buffer; no client code changes.
using storage_class = rgb8_storage;

}  // namespace vl
