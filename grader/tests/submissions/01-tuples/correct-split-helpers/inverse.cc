// Gauss-Jordan elimination with partial pivoting on the augmented 4 x 8 array [m | I].
// Rows are never moved: an index array says which stored row is in each position.
#include <array>
#include <cmath>

#include "stage_01.hh"

namespace vl::stage01 {

matrix inverse(const matrix& m) {
    std::array<std::array<double, 8>, 4> aug{};
    for (int r = 0; r < 4; ++r) {
        const auto ur = static_cast<std::size_t>(r);
        for (int c = 0; c < 4; ++c) aug[ur][static_cast<std::size_t>(c)] = m(r, c);
        aug[ur][4 + ur] = 1;
    }
    std::array<std::size_t, 4> at{0, 1, 2, 3};  // position i holds stored row at[i]

    for (std::size_t k = 0; k < 4; ++k) {
        std::size_t best = k;
        for (std::size_t i = k + 1; i < 4; ++i)
            if (std::abs(aug[at[i]][k]) > std::abs(aug[at[best]][k])) best = i;
        if (aug[at[best]][k] == 0) {
            matrix undefined;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) undefined(r, c) = NaN;
            return undefined;
        }
        std::swap(at[best], at[k]);
        auto& pivot_row = aug[at[k]];
        const double pivot = pivot_row[k];
        for (double& e : pivot_row) e /= pivot;
        for (std::size_t i = 0; i < 4; ++i) {
            if (i == k) continue;
            auto& row = aug[at[i]];
            const double factor = row[k];
            for (std::size_t c = 0; c < 8; ++c) row[c] -= factor * pivot_row[c];
        }
    }
    matrix x;
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t c = 0; c < 4; ++c) x(static_cast<int>(i), static_cast<int>(c)) = aug[at[i]][4 + c];
    return x;
}

}  // namespace vl::stage01
