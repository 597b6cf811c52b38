// Stage 01: the transform builders. What each must return is in stage_01.hh; the public
// tests are in tests/transforms_test.cc.
#include "stage_01.hh"
#include "vl/error.hh"
#include "vl/not_implemented.hh"

namespace vl::stage01 {

matrix translate_matrix([[maybe_unused]] const vector& offset) {
    // TODO: start from the identity (a default-constructed matrix) and put the offset
    //       where a point's w == 1 picks it up and a vector's w == 0 does not. Which
    //       column of m * p does w multiply?
    throw not_implemented_error();
}

matrix scale_matrix([[maybe_unused]] double sx, [[maybe_unused]] double sy, [[maybe_unused]] double sz) {
    // TODO: one factor per axis; the bottom-right element stays 1.
    throw not_implemented_error();
}

matrix rotate_x_matrix([[maybe_unused]] double radians) {
    // TODO: x stays put; y and z turn in their plane. Check your signs with the
    //       quarter turn of the contract: +y must go to +z, not to -z.
    throw not_implemented_error();
}

matrix rotate_y_matrix([[maybe_unused]] double radians) {
    // TODO: y stays put. Careful: the right-handed order about y is z then x, so a quarter
    //       turn takes +z to +x (the sine's sign is where people slip).
    throw not_implemented_error();
}

matrix rotate_z_matrix([[maybe_unused]] double radians) {
    // TODO: z stays put; a quarter turn takes +x to +y.
    throw not_implemented_error();
}

matrix rotate_matrix([[maybe_unused]] const vector& axis, [[maybe_unused]] double radians) {
    // TODO: reject a zero axis with vl::usage_error (say what is wrong and what to do).
    // TODO: make the axis a unit vector from its x, y and z only. How long can an axis be
    //       before squaring its components overflows? (<cmath> has a tool for this.)
    // TODO: build the rotation about a unit axis: look up Rodrigues' rotation formula and
    //       cite where you found it. Check it against rotate_x/y/z_matrix.
    // TODO: the formula needs 1 - cos(angle). What happens to that difference for a tiny
    //       angle, and is there an equal expression that does not subtract?
    throw not_implemented_error();
}

matrix shear_matrix([[maybe_unused]] double shx, [[maybe_unused]] double shy) {
    // TODO: x gains shx times z and y gains shy times z; z and w are unchanged.
    throw not_implemented_error();
}

matrix look_at_matrix([[maybe_unused]] const point& eye, [[maybe_unused]] const point& look_at,
                      [[maybe_unused]] const vector& up) {
    // TODO: reject eye == look_at, and an up that is zero or parallel to the view, with
    //       vl::usage_error.
    // TODO: build three perpendicular unit vectors from the view direction and up: the
    //       eye's right, its true up, and the direction it looks away from. Which cross
    //       product, in which order, gives "right" in a right-handed frame?
    // TODO: a rotation that takes those three vectors to +x, +y and +z is easy to write
    //       down (what is the inverse of a rotation?). It must also take the eye to the
    //       origin: which comes first, the move or the turn, and where does that put the
    //       translation column?
    throw not_implemented_error();
}

}  // namespace vl::stage01
