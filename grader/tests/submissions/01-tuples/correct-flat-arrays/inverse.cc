// Gauss-Jordan elimination with partial pivoting on a flat 4 x 8 array (row-major),
// with the standard algorithms doing the searching and the swapping.
#include <algorithm>
#include <array>
#include <cmath>

#include "stage_01.hh"

namespace vl::stage01 {

matrix inverse(const matrix& m) {
    constexpr std::size_t width = 8;
    std::array<double, 4 * width> a{};
    for (std::size_t r = 0; r < 4; ++r) {
        for (std::size_t c = 0; c < 4; ++c) a[r * width + c] = m(static_cast<int>(r), static_cast<int>(c));
        a[r * width + 4 + r] = 1;
    }
    auto row = [&](std::size_t r) { return a.begin() + static_cast<std::ptrdiff_t>(r * width); };

    for (std::size_t k = 0; k < 4; ++k) {
        std::array<std::size_t, 4> candidates{};
        for (std::size_t i = 0; i < 4; ++i) candidates[i] = i;
        const auto best = std::max_element(candidates.begin() + static_cast<std::ptrdiff_t>(k), candidates.end(),
                                           [&](std::size_t i, std::size_t j) {
                                               return std::fabs(a[i * width + k]) < std::fabs(a[j * width + k]);
                                           });
        const std::size_t p = *best;
        if (a[p * width + k] == 0) {
            matrix nan_matrix;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) nan_matrix(r, c) = NaN;
            return nan_matrix;
        }
        if (p != k) std::swap_ranges(row(p), row(p) + width, row(k));
        const double pivot = a[k * width + k];
        std::transform(row(k), row(k) + width, row(k), [pivot](double e) { return e / pivot; });
        for (std::size_t r = 0; r < 4; ++r) {
            if (r == k) continue;
            const double f = a[r * width + k];
            std::transform(row(r), row(r) + width, row(k), row(r), [f](double e, double pk) { return e - f * pk; });
        }
    }
    matrix x;
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c) x(static_cast<int>(r), static_cast<int>(c)) = a[r * width + 4 + c];
    return x;
}

}  // namespace vl::stage01
