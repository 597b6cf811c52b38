// The infinite plane in the form n . p = offset, with n unit.
#include <cmath>
#include <ostream>

#include "numbers.hh"
#include "stage_02.hh"

namespace vl::stage02 {

namespace {

bool finite(double x, double y, double z) { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
bool good_normal(const vector& n) {
    if (!finite(n.x, n.y, n.z)) return false;
    const vector u = vector(n.x, n.y, n.z).unit();
    return finite(u.x, u.y, u.z) && std::fabs(u.length() - 1) < 1e-9;
}

class plane final : public primitive {
public:
    plane(const point& on, const vector& normal) { set_geometry(on, normal); }

    std::string type_name() const override { return "PLANE"; }

    vector normal(const point&) const override { return unit_; }
    bool contains(const point&) const override { return false; }

    void read(scene_reader& in) override {
        point on = point_;
        vector n = normal_;
        read_with_surface(in, {{"point", [&] {
                                    const source_location where = in.peek().where;
                                    on = in.read_point("point of PLANE").homogenized();
                                    if (!finite(on.x, on.y, on.z)) in.fail(where, "point of PLANE must be a finite point");
                                }},
                               {"normal", [&] {
                                    const source_location where = in.peek().where;
                                    n = in.read_vector("normal of PLANE");
                                    if (!good_normal(n)) in.fail(where, "normal of PLANE must be a finite, non-zero vector");
                                }}});
        set_geometry(on, n);
    }
    void write(std::ostream& s) const override {
        s << "PLANE { point";
        for (const double x : {point_.x, point_.y, point_.z}) {
            s << ' ';
            write_number(s, x);
        }
        s << " normal";
        for (const double x : {normal_.x, normal_.y, normal_.z}) {
            s << ' ';
            write_number(s, x);
        }
        write_surface(s);
        s << " }";
    }

private:
    void set_geometry(const point& on, const vector& normal) {
        point_ = on.homogenized();
        normal_ = vector(normal.x, normal.y, normal.z);
        unit_ = normal_.unit();
        offset_ = unit_.x * point_.x + unit_.y * point_.y + unit_.z * point_.z;
    }

    intersection find_intersection(const ray& r) const override {
        const double speed = unit_ * r.direction();
        if (speed == 0) return intersection::none();
        const point& o = r.origin();
        const double t = (offset_ - (unit_.x * o.x + unit_.y * o.y + unit_.z * o.z)) / speed;
        if (!std::isfinite(t) || !(t > std::fabs(zero_t()))) return intersection::none();
        return intersection::at(t, this);
    }

    point point_;
    vector normal_, unit_;
    double offset_ = 0;
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    const point p = point_on_plane.homogenized();
    if (!finite(p.x, p.y, p.z) || !good_normal(normal))
        throw usage_error("make_plane: the point must be finite and the normal a finite, non-zero vector");
    return std::make_unique<plane>(p, normal);
}

}  // namespace vl::stage02
