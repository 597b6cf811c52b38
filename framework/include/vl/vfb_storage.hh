#pragma once
/// \file
/// \brief How vl::vfb keeps its cells whatever their storage (the implementation's, not
/// for students: use vfb.hh).
///
/// vl::vfb holds its cells behind detail::storage_interface; detail::storage_model<S>
/// implements it for a storage policy S (pixel.hh), built-in or a program's own, so that
/// vl::vfb::with_storage<S>() works for any S. Nothing here is part of the framework's
/// interface.

#include "vl/pixel.hh"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <typeinfo>
#include <vector>

namespace vl {

namespace detail {

// What vfb needs from a storage, whatever it is; storage_model<S> implements it for a
// storage policy S. Rows are given by the index of their first cell; n cells follow.
class storage_interface {
public:
    virtual ~storage_interface() = default;
    virtual std::string_view name() const = 0;
    virtual std::size_t bytes_per_pixel() const = 0;
    virtual int natural_channels() const = 0;
    virtual const std::type_info& storage_type() const = 0;
    virtual void* cells() = 0;
    virtual void put(std::size_t i, const vfb_pixel& p) = 0;
    virtual vfb_pixel get(std::size_t i) const = 0;
    virtual void clear() = 0;
    // Bulk: read n cells as 8-bit sRGB or linear float samples with `channels` channels
    // (1 gray, 2 gray+alpha, 3 RGB, 4 RGBA), or replace n cells with them (a load, so no
    // z rule: what was there is cleared first).
    virtual void read_srgb8(std::size_t first, std::size_t n, int channels, std::uint8_t* out) const = 0;
    virtual void read_linear(std::size_t first, std::size_t n, int channels, float* out) const = 0;
    virtual void write_srgb8(std::size_t first, std::size_t n, int channels, const std::uint8_t* in) = 0;
    virtual void write_linear(std::size_t first, std::size_t n, int channels, const float* in) = 0;
};

template <class S> constexpr bool has_alpha() {
    if constexpr (requires { S::has_alpha; }) return S::has_alpha;
    else return false;
}
template <class S> constexpr int srgb8_channels() {
    if constexpr (requires { S::srgb8_channels; }) return S::srgb8_channels;
    else return 0;
}

// Spreads a vfb_pixel over `channels` samples: gray is luminance, alpha is az for storages
// that keep alpha and opaque for the others.
template <class S> void pixel_to_linear(const vfb_pixel& p, int channels, float* out) {
    const double alpha = has_alpha<S>() ? p.az() : 1.0;
    switch (channels) {
    case 1: out[0] = static_cast<float>(p.gray()); break;
    case 2: out[0] = static_cast<float>(p.gray()); out[1] = static_cast<float>(alpha); break;
    case 3: out[0] = static_cast<float>(p.r()); out[1] = static_cast<float>(p.g()); out[2] = static_cast<float>(p.b()); break;
    default:
        out[0] = static_cast<float>(p.r()); out[1] = static_cast<float>(p.g()); out[2] = static_cast<float>(p.b());
        out[3] = static_cast<float>(alpha);
    }
}
template <class S> vfb_pixel linear_to_pixel(int channels, const float* in) {
    const bool gray = channels <= 2, alpha = channels == 2 || channels == 4;
    const double az = has_alpha<S>() && alpha ? in[channels - 1] : vfb_pixel::no_az;
    return gray ? vfb_pixel(az, in[0], in[0], in[0]) : vfb_pixel(az, in[0], in[1], in[2]);
}

template <class S> class storage_model final : public storage_interface {
public:
    explicit storage_model(std::size_t n) : cells_(n) { clear(); }
    std::string_view name() const override { return S::name; }
    std::size_t bytes_per_pixel() const override { return S::bytes_per_pixel; }
    int natural_channels() const override { return S::natural_channels; }
    const std::type_info& storage_type() const override { return typeid(S); }
    void* cells() override { return cells_.data(); }
    void put(std::size_t i, const vfb_pixel& p) override { S::store(cells_[i], p); }
    vfb_pixel get(std::size_t i) const override { return S::load(cells_[i]); }
    void clear() override { for (auto& c : cells_) S::clear(c); }

    void read_srgb8(std::size_t first, std::size_t n, int channels, std::uint8_t* out) const override {
        if (channels == srgb8_channels<S>()) {  // the cells are the file's bytes: one copy
            std::memcpy(out, &cells_[first], n * sizeof(typename S::cell));
            return;
        }
        float lin[4];
        for (std::size_t i = 0; i < n; ++i) {
            pixel_to_linear<S>(S::load(cells_[first + i]), channels, lin);
            for (int c = 0; c < channels; ++c) {
                const bool alpha = (channels == 2 || channels == 4) && c == channels - 1;
                out[i * channels + c] = alpha ? static_cast<std::uint8_t>(std::lround(std::clamp(lin[c], 0.0f, 1.0f) * 255))
                                              : linear_to_srgb8(lin[c]);
            }
        }
    }
    void read_linear(std::size_t first, std::size_t n, int channels, float* out) const override {
        for (std::size_t i = 0; i < n; ++i) pixel_to_linear<S>(S::load(cells_[first + i]), channels, out + i * channels);
    }
    void write_srgb8(std::size_t first, std::size_t n, int channels, const std::uint8_t* in) override {
        if (channels == srgb8_channels<S>()) {
            std::memcpy(&cells_[first], in, n * sizeof(typename S::cell));
            return;
        }
        float lin[4];
        for (std::size_t i = 0; i < n; ++i) {
            for (int c = 0; c < channels; ++c) {
                const bool alpha = (channels == 2 || channels == 4) && c == channels - 1;
                const std::uint8_t v = in[i * channels + c];
                lin[c] = alpha ? v / 255.0f : srgb8_to_linear(v);
            }
            replace(cells_[first + i], linear_to_pixel<S>(channels, lin));
        }
    }
    void write_linear(std::size_t first, std::size_t n, int channels, const float* in) override {
        for (std::size_t i = 0; i < n; ++i) replace(cells_[first + i], linear_to_pixel<S>(channels, in + i * channels));
    }

private:
    static void replace(typename S::cell& c, const vfb_pixel& p) { S::clear(c); S::store(c, p); }
    std::vector<typename S::cell> cells_;
};

}  // namespace detail

}  // namespace vl
