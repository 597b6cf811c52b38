// The inverse through an LU factorization with partial pivoting, P m = L U, then one
// forward and one back substitution for each column of the identity.
#include <array>
#include <cmath>

#include "stage_01.hh"

namespace vl::stage01 {

matrix inverse(const matrix& m) {
    std::array<std::array<double, 4>, 4> lu{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) lu[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = m(r, c);
    std::array<std::size_t, 4> perm{0, 1, 2, 3};  // row i of P m is row perm[i] of m

    for (std::size_t k = 0; k < 4; ++k) {
        std::size_t p = k;
        for (std::size_t r = k + 1; r < 4; ++r)
            if (std::abs(lu[r][k]) > std::abs(lu[p][k])) p = r;
        if (lu[p][k] == 0) {
            const double n = NaN;
            return {n, n, n, n, n, n, n, n, n, n, n, n, n, n, n, n};
        }
        std::swap(lu[p], lu[k]);
        std::swap(perm[p], perm[k]);
        for (std::size_t r = k + 1; r < 4; ++r) {
            const double l = lu[r][k] / lu[k][k];
            lu[r][k] = l;  // L's multiplier, stored where the zero would be
            for (std::size_t c = k + 1; c < 4; ++c) lu[r][c] -= l * lu[k][c];
        }
    }

    matrix x;
    for (std::size_t col = 0; col < 4; ++col) {
        // Solve L y = P e_col, then U x = y.
        std::array<double, 4> y{};
        for (std::size_t i = 0; i < 4; ++i) {
            double sum = perm[i] == col ? 1.0 : 0.0;
            for (std::size_t j = 0; j < i; ++j) sum -= lu[i][j] * y[j];
            y[i] = sum;
        }
        for (std::size_t ii = 4; ii-- > 0;) {
            double sum = y[ii];
            for (std::size_t j = ii + 1; j < 4; ++j) sum -= lu[ii][j] * y[j];
            y[ii] = sum / lu[ii][ii];
        }
        for (std::size_t i = 0; i < 4; ++i) x(static_cast<int>(i), static_cast<int>(col)) = y[i];
    }
    return x;
}

}  // namespace vl::stage01
