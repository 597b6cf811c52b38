#pragma once
/// \file
/// \brief The parameters of the staged shapes as a scene file gives them: reading and
/// writing them, and the checks their factories make. Reading and writing input right is
/// not the lesson: these are shared so that every implementation of a shape reads the same
/// keys, refuses bad values with the same clear message and writes what it reads back.
///
/// An object's read() fills a parameter struct through primitive::read_with_surface() and
/// keeps what it needs; its write() writes the struct, then its surface, then ` }`:
///
///     void read(scene_reader& in) override {
///         shapes::sphere_params p{center_, radius_};
///         read_with_surface(in, p.properties(in));
///         set_geometry(p.center, p.radius);
///     }
///     void write(std::ostream& s) const override {
///         shapes::sphere_params{center_, radius_}.write(s);
///         write_surface(s);
///         s << " }";
///     }
///
/// Each write() writes its numbers with std::numeric_limits<double>::max_digits10 digits,
/// so that reading them back gives the same doubles, and leaves the stream's precision as
/// it was.

#include <iosfwd>
#include <string>
#include <vector>

#include "vl/scene_reader.hh"
#include "vl/tuples.hh"

namespace vl::checks {

/// True when x, y and z are finite (w is not looked at: homogenize a point first).
bool finite(const point& p);
/// True when x, y and z are finite.
bool finite(const vector& v);
/// A normal that unit() can make unit: finite, not zero, not so large or small that its
/// length overflows or underflows (w is not looked at).
bool usable_normal(const vector& n);
/// Why three (homogenized) points are not a triangle, or "" when they are: a vertex that is
/// not finite, or vertices on one line, which means the sine of the angle at a is below
/// 1e-12 (the cross product has no usable direction).
std::string triangle_problem(const point& a, const point& b, const point& c);
/// True when `a` is below `b` in x, y and z: the corners of a box with volume.
bool below(const point& a, const point& b);
/// Why `m` cannot place an object (an element not finite, not affine, singular), or nullptr
/// when it can.
const char* unusable_matrix(const matrix& m);

}  // namespace vl::checks

namespace vl::shapes {

/// `SPHERE { center X Y Z  radius R ... }`.
struct sphere_params {
    point center;       ///< `center`, homogenized
    double radius = 1;  ///< `radius`, > 0

    /// `center` (a finite point, homogenized) and `radius` (> 0), read into this struct.
    std::vector<scene_reader::property> properties(scene_reader& in);
    /// `SPHERE { center X Y Z radius R`.
    void write(std::ostream& s) const;
};

/// `PLANE { point X Y Z  normal X Y Z ... }`.
struct plane_params {
    point point_on_plane;  ///< `point`, homogenized
    vector normal;  ///< as given (not unit), so that write() writes what was read

    /// `point` (a finite point, homogenized) and `normal` (w set to 0; a usable normal).
    std::vector<scene_reader::property> properties(scene_reader& in);
    /// `PLANE { point X Y Z normal X Y Z`.
    void write(std::ostream& s) const;
};

/// `TRIANGLE { a X Y Z  b X Y Z  c X Y Z ... }`.
struct triangle_params {
    point a;  ///< `a`, homogenized
    point b;  ///< `b`, homogenized
    point c;  ///< `c`, homogenized

    /// `a`, `b` and `c`, each homogenized; check() them once all are read.
    std::vector<scene_reader::property> properties(scene_reader& in);
    /// Fails at `where` (the position before the object's `{`) when the three vertices
    /// are not a triangle (checks::triangle_problem()).
    void check(scene_reader& in, const source_location& where) const;
    /// `TRIANGLE { a X Y Z b X Y Z c X Y Z`.
    void write(std::ostream& s) const;
};

/// `POLYGON { vertices (X, Y, Z) (X, Y, Z) (X, Y, Z) ... ... }`.
struct polygon_params {
    std::vector<point> vertices;  ///< `vertices` in order, each homogenized

    /// `vertices`: one or more `(x, y, z)`, each homogenized, that find_polygon_problem()
    /// accepts; a scene file's error points at the vertex at fault.
    std::vector<scene_reader::property> properties(scene_reader& in);
    /// `POLYGON { vertices (X, Y, Z) ...`.
    void write(std::ostream& s) const;
};

/// `FRACSPH { center X Y Z  radius R  depth D  ratio Q ... }`.
struct frac_sphere_params {
    static constexpr int max_depth = 7;  ///< the deepest `depth` accepted

    point center;       ///< `center`, homogenized
    double radius = 1;  ///< `radius`, > 0
    int depth = 0;      ///< `depth`, 0 to max_depth
    double ratio = 0.5; ///< `ratio`, between 0 and 1

    /// `center` (a finite point, homogenized), `radius` (> 0), `depth` (0 to max_depth)
    /// and `ratio` (between 0 and 1), for scene_reader::read_block().
    std::vector<scene_reader::property> properties(scene_reader& in);
    /// `FRACSPH { center X Y Z radius R depth D ratio Q`.
    void write(std::ostream& s) const;
};

/// `BOX { min X Y Z  max X Y Z ... }`.
struct box_params {
    point lo;  ///< `min`, homogenized
    point hi;  ///< `max`, homogenized

    /// `min` and `max` (finite points, homogenized), for scene_reader::read_block().
    /// `where` becomes where the last corner read starts (where the block starts when
    /// none is), for the caller's check that min is below max (checks::below()).
    std::vector<scene_reader::property> properties(scene_reader& in, source_location& where);
    /// `BOX { min X Y Z max X Y Z`.
    void write(std::ostream& s) const;
};

/// Reads the start of `BVH { leaf_size K  OBJECT ... }`: the `{` and, when it follows,
/// `leaf_size K` (1 to 64). Returns K, or `leaf_size` when the key is not there.
int read_bvh_leaf_size(scene_reader& in, int leaf_size);

/// How a TRANSFORM's steps become matrices: stage 01's functions (the framework does not
/// depend on a stage).
struct transform_step_makers {
    matrix (*scale)(double sx, double sy, double sz);      ///< stage 01's scale_matrix()
    matrix (*rotate)(const vector& axis, double radians);  ///< stage 01's rotate_matrix()
    matrix (*translate)(const vector& offset);             ///< stage 01's translate_matrix()
};

/// Reads the values of the TRANSFORM step `step` (whose word has been read):
/// `scale X Y Z`, `rotate X Y Z DEGREES` (a non-zero axis), `translate X Y Z` or
/// `matrix M11 ... M44` (row by row), and returns its matrix; fails at the word for any
/// other.
matrix read_transform_step(scene_reader& in, const token& step, const transform_step_makers& make);

/// `TRANSFORM { matrix M11 ... M44` (row by row).
void write_transform_matrix(std::ostream& s, const matrix& to_world);

}  // namespace vl::shapes
