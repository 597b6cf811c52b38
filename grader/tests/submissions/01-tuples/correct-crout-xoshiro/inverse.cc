// The inverse from a Crout LU factorization with partial pivoting: P m = L U with a unit
// diagonal in U. Then m^-1 = U^-1 L^-1 P, each triangular inverse by substitution.
#include <cmath>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

using mat = double[4][4];

}  // namespace

matrix inverse(const matrix& m) {
    mat a;
    int perm[4] = {0, 1, 2, 3};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) a[r][c] = m(r, c);

    // Crout: column j of L, then row j of U, with the pivot chosen among the candidates
    // of column j of L (what Gaussian elimination would have left there).
    for (int j = 0; j < 4; ++j) {
        for (int i = j; i < 4; ++i) {
            double sum = a[i][j];
            for (int k = 0; k < j; ++k) sum -= a[i][k] * a[k][j];
            a[i][j] = sum;
        }
        int p = j;
        for (int i = j + 1; i < 4; ++i)
            if (std::fabs(a[i][j]) > std::fabs(a[p][j])) p = i;
        if (a[p][j] == 0) {
            matrix undefined;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) undefined(r, c) = NaN;
            return undefined;
        }
        if (p != j) {
            for (int c = 0; c < 4; ++c) {
                const double t = a[p][c];
                a[p][c] = a[j][c];
                a[j][c] = t;
            }
            const int t = perm[p];
            perm[p] = perm[j];
            perm[j] = t;
        }
        for (int c = j + 1; c < 4; ++c) {
            double sum = a[j][c];
            for (int k = 0; k < j; ++k) sum -= a[j][k] * a[k][c];
            a[j][c] = sum / a[j][j];
        }
    }

    // L^-1 (lower triangle, general diagonal) and U^-1 (upper, unit diagonal).
    mat li = {}, ui = {};
    for (int c = 0; c < 4; ++c) {
        li[c][c] = 1 / a[c][c];
        for (int r = c + 1; r < 4; ++r) {
            double sum = 0;
            for (int k = c; k < r; ++k) sum -= a[r][k] * li[k][c];
            li[r][c] = sum / a[r][r];
        }
    }
    for (int c = 0; c < 4; ++c) {
        ui[c][c] = 1;
        for (int r = c - 1; r >= 0; --r) {
            double sum = 0;
            for (int k = r + 1; k <= c; ++k) sum -= a[r][k] * ui[k][c];
            ui[r][c] = sum;
        }
    }
    // m^-1 = U^-1 L^-1 P: column perm[j] of the result is column j of U^-1 L^-1.
    matrix x;
    for (int r = 0; r < 4; ++r)
        for (int j = 0; j < 4; ++j) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += ui[r][k] * li[k][j];
            x(r, perm[j]) = sum;
        }
    return x;
}

}  // namespace vl::stage01
