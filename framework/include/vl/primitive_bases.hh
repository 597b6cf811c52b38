#pragma once
/// \file
/// \brief The bases of stage 02's shapes: each holds one shape's geometry, names it, reads
/// and writes it (through vl/shape_params.hh) and checks a factory's arguments, so that a
/// shape's own file is only its geometry: find_intersection(), normal(), the bounds and
/// what it precomputes.
///
/// A shape derives from its base and writes no constructor: its factory calls the base's
/// make(), which checks the arguments (the check of the factory), makes the shape and sets
/// its geometry, which calls geometry_changed() once; the base's read() calls it again
/// after reading (a base's constructor could not call a derived class's override):
///
///     class sphere final : public shapes::sphere_base {
///         ...
///     private:
///         void geometry_changed() override { ... }  // precompute from center_ and radius_
///         intersection find_intersection(const ray& r) const override;
///     };
///
///     std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
///         return shapes::sphere_base::make<sphere>(center, radius);
///     }
///
/// Every member is virtual or protected where a shape may want its own: a shape may
/// override read() or write(), and call set_geometry() from its own read().

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "vl/primitive.hh"
#include "vl/scene_reader.hh"
#include "vl/tuples.hh"

namespace vl::shapes {

/// \brief A sphere's geometry: `SPHERE { center X Y Z  radius R ... }`.
class sphere_base : public primitive {
public:
    /// `"SPHERE"`.
    std::string type_name() const override;
    /// Reads `{ center X Y Z  radius R ...surface keys... }` (sphere_params), then
    /// set_geometry().
    void read(scene_reader& in) override;
    /// Writes what read() reads back as the same sphere, numbers at full precision.
    void write(std::ostream& s) const override;

    /// The check of make_sphere(): throws vl::usage_error ("make_sphere: ...") when
    /// `center` is not finite or `radius` is not a finite number > 0.
    static void check(const point& center, double radius);

    /// A `shape` (a class derived from this one, default-constructible) of this geometry,
    /// as make_sphere() makes it: check()s the arguments, makes the shape and
    /// set_geometry()s it, which calls its geometry_changed() once.
    template <class shape>
    static std::unique_ptr<shape> make(const point& center, double radius) {
        check(center, radius);
        auto made = std::make_unique<shape>();
        static_cast<sphere_base&>(*made).set_geometry(center, radius);
        return made;
    }

protected:
    /// No geometry yet: make() sets it.
    sphere_base() = default;
    /// Stores the geometry (as set_geometry() does, without calling geometry_changed()).
    sphere_base(const point& center, double radius);

    /// Stores `center` (homogenized) and `radius`, then calls geometry_changed().
    void set_geometry(const point& center, double radius);
    /// Called after every change of the geometry (read(), set_geometry()); a derived class
    /// precomputes here what its find_intersection() should not recompute for every ray.
    /// Does nothing by default.
    virtual void geometry_changed() {}

    point center_;       ///< the centre, homogenized
    double radius_ = 1;  ///< the radius, > 0
};

/// \brief An infinite plane's geometry: `PLANE { point X Y Z  normal X Y Z ... }`.
///
/// A flat object: contains() is false. The plane is unbounded, so min_point() and
/// max_point() keep the default NaN_point ("no box").
class plane_base : public primitive {
public:
    /// `"PLANE"`.
    std::string type_name() const override;
    /// False: a flat object has no inside.
    bool contains(const point& p) const override;
    /// Reads `{ point X Y Z  normal X Y Z ...surface keys... }` (plane_params), then
    /// set_geometry().
    void read(scene_reader& in) override;
    /// Writes what read() reads back as the same plane, the normal as given.
    void write(std::ostream& s) const override;

    /// The check of make_plane(): throws vl::usage_error ("make_plane: ...") when
    /// `point_on_plane` is not finite or `normal` is not a usable normal.
    static void check(const point& point_on_plane, const vector& normal);

    /// A `shape` (a class derived from this one, default-constructible) of this geometry,
    /// as make_plane() makes it: check()s the arguments, makes the shape and
    /// set_geometry()s it, which calls its geometry_changed() once.
    template <class shape>
    static std::unique_ptr<shape> make(const point& point_on_plane, const vector& normal) {
        check(point_on_plane, normal);
        auto made = std::make_unique<shape>();
        static_cast<plane_base&>(*made).set_geometry(point_on_plane, normal);
        return made;
    }

protected:
    /// No geometry yet: make() sets it.
    plane_base() = default;
    /// Stores the geometry (as set_geometry() does, without calling geometry_changed()).
    plane_base(const point& point_on_plane, const vector& normal);

    /// Stores `point_on_plane` (homogenized) and `normal` (w 0, not made unit), then calls
    /// geometry_changed().
    void set_geometry(const point& point_on_plane, const vector& normal);
    /// Called after every change of the geometry (read(), set_geometry()); a derived class
    /// precomputes here what its find_intersection() should not recompute for every ray
    /// (the unit normal?). Does nothing by default.
    virtual void geometry_changed() {}

    point point_;    ///< a point on the plane, homogenized
    vector normal_;  ///< the normal as given (not unit), so that write() writes what was read
};

/// \brief A triangle's geometry: `TRIANGLE { a X Y Z  b X Y Z  c X Y Z ... }`.
///
/// A flat object: contains() is false.
class triangle_base : public primitive {
public:
    /// `"TRIANGLE"`.
    std::string type_name() const override;
    /// False: a flat object has no inside.
    bool contains(const point& p) const override;
    /// Reads `{ a X Y Z  b X Y Z  c X Y Z ...surface keys... }` (triangle_params), fails
    /// at the object when the vertices are not a triangle (checks::triangle_problem()),
    /// then set_geometry().
    void read(scene_reader& in) override;
    /// Writes what read() reads back as the same triangle, numbers at full precision.
    void write(std::ostream& s) const override;

    /// The check of make_triangle(): throws vl::usage_error ("make_triangle: ...") when
    /// the vertices (homogenized) are not a triangle (checks::triangle_problem()).
    static void check(const point& a, const point& b, const point& c);

    /// A `shape` (a class derived from this one, default-constructible) of this geometry,
    /// as make_triangle() makes it: check()s the arguments, makes the shape and
    /// set_geometry()s it, which calls its geometry_changed() once.
    template <class shape>
    static std::unique_ptr<shape> make(const point& a, const point& b, const point& c) {
        check(a, b, c);
        auto made = std::make_unique<shape>();
        static_cast<triangle_base&>(*made).set_geometry(a, b, c);
        return made;
    }

protected:
    /// No geometry yet: make() sets it.
    triangle_base() = default;
    /// Stores the geometry (as set_geometry() does, without calling geometry_changed()).
    triangle_base(const point& a, const point& b, const point& c);

    /// Stores the vertices (each homogenized), then calls geometry_changed().
    void set_geometry(const point& a, const point& b, const point& c);
    /// Called after every change of the geometry (read(), set_geometry()); a derived class
    /// precomputes here what its find_intersection() should not recompute for every ray.
    /// Does nothing by default.
    virtual void geometry_changed() {}

    point a_;  ///< the first vertex, homogenized
    point b_;  ///< the second vertex, homogenized
    point c_;  ///< the third vertex, homogenized
};

/// \brief A convex planar polygon's geometry: `POLYGON { vertices (X, Y, Z) ... ... }`.
///
/// A flat object: contains() is false.
class polygon_base : public primitive {
public:
    /// `"POLYGON"`.
    std::string type_name() const override;
    /// False: a flat object has no inside.
    bool contains(const point& p) const override;
    /// Reads `{ vertices (X, Y, Z) ... ...surface keys... }` (polygon_params, which fails
    /// at the vertex at fault), then set_geometry().
    void read(scene_reader& in) override;
    /// Writes what read() reads back as the same polygon, numbers at full precision.
    void write(std::ostream& s) const override;

    /// The check of make_polygon(): throws vl::usage_error ("make_polygon: ...") when the
    /// vertices (homogenized) are not a convex planar polygon (find_polygon_problem()).
    static void check(const std::vector<point>& vertices);

    /// A `shape` (a class derived from this one, default-constructible) of this geometry,
    /// as make_polygon() makes it: check()s the arguments, makes the shape and
    /// set_geometry()s it, which calls its geometry_changed() once.
    template <class shape>
    static std::unique_ptr<shape> make(std::vector<point> vertices) {
        check(vertices);
        auto made = std::make_unique<shape>();
        static_cast<polygon_base&>(*made).set_geometry(std::move(vertices));
        return made;
    }

protected:
    /// No geometry yet: make() sets it.
    polygon_base() = default;
    /// Stores the geometry (as set_geometry() does, without calling geometry_changed()).
    explicit polygon_base(std::vector<point> vertices);

    /// Stores the vertices (each homogenized; checked already), then calls
    /// geometry_changed().
    void set_geometry(std::vector<point> vertices);
    /// Called after every change of the geometry (read(), set_geometry()); a derived class
    /// precomputes here what its find_intersection() should not recompute for every ray
    /// (the normal? the box?). Does nothing by default.
    virtual void geometry_changed() {}

    std::vector<point> vertices_;  ///< the vertices in order, each homogenized
};

}  // namespace vl::shapes
