// The inverse by Gauss-Jordan elimination with complete pivoting: at each step the
// largest remaining element of the whole lower-right block is the pivot. Row swaps are
// done on both matrices; column swaps permute the unknowns, so they are undone on the
// rows of the result at the end.
#include <array>
#include <cmath>
#include <utility>

#include "stage_01.hh"

namespace vl::stage01 {

matrix inverse(const matrix& m) {
    using row = std::array<double, 4>;
    std::array<row, 4> a{}, b{};
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c) {
            a[r][c] = m(static_cast<int>(r), static_cast<int>(c));
            b[r][c] = r == c ? 1 : 0;
        }
    std::array<std::size_t, 4> column_of{0, 1, 2, 3};  // column k of a holds unknown column_of[k]

    for (std::size_t k = 0; k < 4; ++k) {
        std::size_t pr = k, pc = k;
        for (std::size_t r = k; r < 4; ++r)
            for (std::size_t c = k; c < 4; ++c)
                if (std::abs(a[r][c]) > std::abs(a[pr][pc])) {
                    pr = r;
                    pc = c;
                }
        if (a[pr][pc] == 0) {
            matrix nan;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) nan(r, c) = NaN;
            return nan;
        }
        std::swap(a[pr], a[k]);
        std::swap(b[pr], b[k]);
        if (pc != k) {
            for (std::size_t r = 0; r < 4; ++r) std::swap(a[r][pc], a[r][k]);
            std::swap(column_of[pc], column_of[k]);
        }
        const double pivot = a[k][k];
        for (std::size_t c = 0; c < 4; ++c) {
            a[k][c] /= pivot;
            b[k][c] /= pivot;
        }
        for (std::size_t r = 0; r < 4; ++r) {
            if (r == k) continue;
            const double f = a[r][k];
            if (f == 0) continue;
            for (std::size_t c = 0; c < 4; ++c) {
                a[r][c] -= f * a[k][c];
                b[r][c] -= f * b[k][c];
            }
        }
    }
    // a is now the identity with permuted unknowns: row k of b is row column_of[k] of the inverse.
    matrix x;
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t c = 0; c < 4; ++c) x(static_cast<int>(column_of[k]), static_cast<int>(c)) = b[k][c];
    return x;
}

}  // namespace vl::stage01
