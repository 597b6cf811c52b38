// The infinite plane: see stage_02.hh for what each function must do, and README.md for
// hints. read() and write() are done; the functions marked TODO are yours.
#include <cmath>
#include <limits>
#include <ostream>

#include "stage_02.hh"
#include "vl/not_implemented.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool finite(const vector& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
// A normal that unit() can make unit: not zero, not so large or small that its length
// overflows or underflows.
bool usable_normal(const vector& n) {
    const vector u = vector(n.x, n.y, n.z).unit();
    return finite(n) && finite(u) && std::fabs(u.length() - 1) < 1e-9;
}

/// \brief The points p with (p - point_on_plane) . normal == 0.
class plane final : public primitive {
public:
    plane(const point& point_on_plane, const vector& normal) { set_geometry(point_on_plane, normal); }

    std::string type_name() const override { return "PLANE"; }

    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the plane's unit normal (the same everywhere).
        throw not_implemented_error();
    }
    bool contains(const point&) const override { return false; }  // a flat object has no inside
    // min_point() and max_point(): a plane is unbounded, so the defaults (NaN_point, "no
    // box") are already right.

    void read(scene_reader& in) override {
        point p = point_;
        vector n = normal_;
        read_with_surface(in, {{"point", [&] {
                                    const source_location where = in.peek().where;
                                    p = in.read_point("point of PLANE").homogenized();
                                    if (!finite(p)) in.fail(where, "point of PLANE must be a finite point (w not 0)");
                                }},
                               {"normal", [&] {
                                    const source_location where = in.peek().where;
                                    n = in.read_vector("normal of PLANE");
                                    n.w = 0;
                                    if (!usable_normal(n)) in.fail(where, "normal of PLANE must not be the zero vector");
                                }}});
        set_geometry(p, n);
    }
    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "PLANE { point " << point_.x << ' ' << point_.y << ' ' << point_.z << " normal " << normal_.x << ' '
          << normal_.y << ' ' << normal_.z;
        s.precision(old_precision);
        write_surface(s);
        s << " }";
    }

private:
    /// Stores the geometry; the constructor calls it, and read() calls it again with what
    /// it read from the scene.
    void set_geometry(const point& point_on_plane, const vector& normal) {
        point_ = point_on_plane.homogenized();
        normal_ = vector(normal.x, normal.y, normal.z);
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // (the unit normal?) belongs here, so that it is also right after read().
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: the hit of r with t > |zero_t()|, or intersection::none().
        // - Put the ray o + t d into (p - point_) . n = 0 and solve for t.
        // - What if the ray runs parallel to the plane? Lies in it? Is nearly parallel?
        //   None of them may return a NaN or an infinite t.
        // - A ray starting on the plane (a reflection leaving it) must not hit it again.
        throw not_implemented_error();
    }

    point point_;    ///< as given, so write() writes what was read
    vector normal_;  ///< as given (not unit), for the same reason
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    if (!finite(point_on_plane.homogenized()) || !usable_normal(normal))
        throw usage_error("make_plane: the point must be finite and the normal a finite, non-zero vector");
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
