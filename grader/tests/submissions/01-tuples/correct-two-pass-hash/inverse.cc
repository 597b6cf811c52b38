// The inverse in two passes over [m | I]: Gaussian elimination with partial pivoting down
// to an upper triangle with a unit diagonal, then elimination upwards from the last row.
#include <cmath>
#include <utility>

#include "stage_01.hh"

namespace vl::stage01 {

matrix inverse(const matrix& m) {
    double a[4][8];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 8; ++c)
            a[r][c] = c < 4 ? m(r, c) : (c - 4 == r ? 1.0 : 0.0);

    // Downwards.
    for (int k = 0; k < 4; ++k) {
        int p = k;
        for (int r = k + 1; r < 4; ++r)
            if (std::abs(a[r][k]) > std::abs(a[p][k])) p = r;
        if (a[p][k] == 0) {
            matrix all_nan;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) all_nan(r, c) = NaN;
            return all_nan;
        }
        if (p != k)
            for (int c = 0; c < 8; ++c) std::swap(a[p][c], a[k][c]);
        const double pivot = a[k][k];
        for (int c = k; c < 8; ++c) a[k][c] /= pivot;
        for (int r = k + 1; r < 4; ++r) {
            const double f = a[r][k];
            for (int c = k; c < 8; ++c) a[r][c] -= f * a[k][c];
        }
    }
    // Upwards: clear the part above the diagonal, last column first.
    for (int k = 3; k > 0; --k)
        for (int r = k - 1; r >= 0; --r) {
            const double f = a[r][k];
            for (int c = k; c < 8; ++c) a[r][c] -= f * a[k][c];
        }

    matrix x;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) x(r, c) = a[r][c + 4];
    return x;
}

}  // namespace vl::stage01
