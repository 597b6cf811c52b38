// The infinite plane: t from the plane equation (p - point) . n = 0.
#include <cmath>
#include <limits>
#include <ostream>

#include "stage_02.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool finite(const vector& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool usable_normal(const vector& n) {
    const vector u = vector(n.x, n.y, n.z).unit();
    return finite(n) && finite(u) && std::fabs(u.length() - 1) < 1e-9;
}

class plane final : public primitive {
public:
    plane(const point& point_on_plane, const vector& normal) { set_geometry(point_on_plane, normal); }

    std::string type_name() const override { return "PLANE"; }

    vector normal(const point&) const override { return unit_normal_; }
    bool contains(const point&) const override { return false; }

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
    void set_geometry(const point& point_on_plane, const vector& normal) {
        point_ = point_on_plane.homogenized();
        normal_ = vector(normal.x, normal.y, normal.z);
        unit_normal_ = normal_.unit();
    }

    intersection find_intersection(const ray& r) const override {
        const double facing = r.direction() * unit_normal_;
        if (facing == 0) return intersection::none();  // parallel, or lying in the plane
        const double t = ((point_ - r.origin()) * unit_normal_) / facing;
        if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
        return intersection::none();
    }

    point point_;
    vector normal_;
    vector unit_normal_;
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    if (!finite(point_on_plane.homogenized()) || !usable_normal(normal))
        throw usage_error("make_plane: the point must be finite and the normal a finite, non-zero vector");
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
