// The infinite plane.
#include <cmath>
#include <ostream>

#include "format.hh"
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
    plane(const point& on, const vector& n) { set(on, n); }

    std::string type_name() const override { return "PLANE"; }

    vector normal(const point&) const override { return unit_; }
    bool contains(const point&) const override { return false; }

    void read(scene_reader& in) override {
        point on = on_;
        vector n = given_;
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
        set(on, n);
    }
    void write(std::ostream& s) const override {
        s << "PLANE { point " << exact(on_.x) << ' ' << exact(on_.y) << ' ' << exact(on_.z) << " normal "
          << exact(given_.x) << ' ' << exact(given_.y) << ' ' << exact(given_.z);
        write_surface(s);
        s << " }";
    }

private:
    void set(const point& on, const vector& n) {
        on_ = on.homogenized();
        given_ = vector(n.x, n.y, n.z);
        unit_ = given_.unit();
    }

    intersection find_intersection(const ray& r) const override {
        const double cosine = r.direction() * unit_;
        const double height = (r.origin() - on_) * unit_;  // signed distance of the origin from the plane
        if (cosine == 0) return intersection::none();
        const double t = -height / cosine;
        if (t > std::fabs(zero_t()) && t < HUGE_VAL) return intersection::at(t, this);
        return intersection::none();
    }

    point on_;
    vector given_, unit_;
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    const point p = point_on_plane.homogenized();
    if (!finite(p.x, p.y, p.z) || !good_normal(normal))
        throw usage_error("make_plane: the point must be finite and the normal a finite, non-zero vector");
    return std::make_unique<plane>(p, normal);
}

}  // namespace vl::stage02
