// Gauss-Jordan elimination with partial pivoting, each row of [m | I] kept as a pair of
// vl::vector (x, y, z, w are the four columns), so row operations read like algebra.
#include <cmath>
#include <utility>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

double& at(vector& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : i == 2 ? v.z : v.w; }

}  // namespace

matrix inverse(const matrix& m) {
    vector left[4] = {m.row(0), m.row(1), m.row(2), m.row(3)};
    vector right[4] = {IDENTITY.row(0), IDENTITY.row(1), IDENTITY.row(2), IDENTITY.row(3)};
    for (int k = 0; k < 4; ++k) {
        int p = k;
        for (int r = k + 1; r < 4; ++r)
            if (std::fabs(at(left[r], k)) > std::fabs(at(left[p], k))) p = r;
        if (at(left[p], k) == 0) {
            const vector undefined(NaN, NaN, NaN, NaN);
            return {undefined, undefined, undefined, undefined};
        }
        std::swap(left[p], left[k]);
        std::swap(right[p], right[k]);
        const double pivot = at(left[k], k);
        left[k] /= pivot;
        right[k] /= pivot;
        at(left[k], k) = 1;  // exactly
        for (int r = 0; r < 4; ++r) {
            if (r == k) continue;
            const double f = at(left[r], k);
            left[r] -= left[k] * f;
            right[r] -= right[k] * f;
            at(left[r], k) = 0;
        }
    }
    return {right[0], right[1], right[2], right[3]};
}

}  // namespace vl::stage01
