// Reference: the 4x4 inverse by Gauss-Jordan elimination with partial pivoting (see
// assignments/01-tuples/stage_01.hh for the method and its error bound; the analysis is
// N. J. Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed., §14.4).
#include <cmath>
#include <utility>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

void swap_rows(matrix& m, int a, int b) {
    for (int c = 0; c < 4; ++c) std::swap(m(a, c), m(b, c));
}

}  // namespace

matrix inverse(const matrix& m) {
    matrix a = m;  // reduced to the identity ...
    matrix x;      // ... while the same row operations turn the identity into the inverse
    for (int k = 0; k < 4; ++k) {
        // Partial pivoting: the largest entry of column k on or below the diagonal.
        // std::isgreater is the quiet comparison: a NaN in m gives a NaN inverse, without
        // raising the floating-point "invalid" flag that `>` would raise.
        int pivot_row = k;
        for (int r = k + 1; r < 4; ++r)
            if (std::isgreater(std::abs(a(r, k)), std::abs(a(pivot_row, k)))) pivot_row = r;
        if (a(pivot_row, k) == 0) {
            // Every candidate is zero: the columns of m are linearly dependent.
            return {NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN, NaN};
        }
        swap_rows(a, k, pivot_row);
        swap_rows(x, k, pivot_row);

        // Divide rather than multiply by a reciprocal: one rounding per element, not two.
        const double pivot = a(k, k);
        for (int c = 0; c < 4; ++c) {
            a(k, c) /= pivot;
            x(k, c) /= pivot;
        }
        // Every multiplier is at most 1 in size (the pivot was the largest), so the
        // rounding errors already in row k are not magnified when it is subtracted.
        for (int r = 0; r < 4; ++r) {
            const double f = a(r, k);
            if (r == k || f == 0) continue;
            for (int c = 0; c < 4; ++c) {
                a(r, c) -= f * a(k, c);
                x(r, c) -= f * x(k, c);
            }
            a(r, k) = 0;  // exactly, whatever the rounding above left there
        }
    }
    return x;
}

}  // namespace vl::stage01
