// Stage 01: the inverse of a 4x4 matrix by Gauss-Jordan elimination with partial
// pivoting. The method, the singular case and the accuracy to aim for are in stage_01.hh;
// the public tests are in tests/inverse_test.cc.
#include "stage_01.hh"
#include "vl/not_implemented.hh"

namespace vl::stage01 {

matrix inverse([[maybe_unused]] const matrix& m) {
    // TODO: keep two matrices: a working copy of m, and the identity beside it. Every row
    //       operation you do to one, do to the other.
    // TODO: for each column k: find the pivot row (partial pivoting: which entry, among
    //       which rows?), swap it into row k, scale row k so the pivot becomes 1, then
    //       clear column k in every other row, above the diagonal as well as below.
    // TODO: if no usable pivot exists in a column, return the all-NaN matrix the contract
    //       asks for (vl::NaN is in vl/tuples.hh).
    // TODO: try a matrix whose m(0, 0) is 0 and one whose m(0, 0) is 1e-20 with pivoting
    //       switched off. The first fails loudly (infinities, NaN); what happens to the
    //       second, and why is that the more dangerous failure?
    throw not_implemented_error();
}

}  // namespace vl::stage01
