// The triangle: inside or outside is decided by three edge functions in the ray's own
// frame (ray_frame.hh), so triangles of a mesh leave no gap; t comes from the plane.
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "numbers.hh"
#include "ray_frame.hh"
#include "stage_02.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

std::string triangle_problem(const point& a, const point& b, const point& c) {
    if (!finite(a) || !finite(b) || !finite(c)) return "every vertex must be a finite point (w not 0)";
    const vector ab = b - a, ac = c - a;
    if (!((ab % ac).length() > 1e-12 * ab.length() * ac.length()))
        return "its vertices a, b and c are on one line (or two coincide): it has no area";
    return "";
}

class triangle final : public primitive {
public:
    triangle(const point& a, const point& b, const point& c) { set_geometry(a, b, c); }

    std::string type_name() const override { return "TRIANGLE"; }

    vector normal(const point&) const override { return normal_; }
    bool contains(const point&) const override { return false; }
    point min_point() const override { return low_; }
    point max_point() const override { return high_; }

    void read(scene_reader& in) override {
        const source_location where = in.peek().where;
        point v[3] = {v_[0], v_[1], v_[2]};
        read_with_surface(in, {{"a", [&] { v[0] = in.read_point("vertex a of TRIANGLE").homogenized(); }},
                               {"b", [&] { v[1] = in.read_point("vertex b of TRIANGLE").homogenized(); }},
                               {"c", [&] { v[2] = in.read_point("vertex c of TRIANGLE").homogenized(); }}});
        if (const std::string problem = triangle_problem(v[0], v[1], v[2]); !problem.empty())
            in.fail(where, "this TRIANGLE is not a triangle: " + problem);
        set_geometry(v[0], v[1], v[2]);
    }
    void write(std::ostream& s) const override {
        s << "TRIANGLE {";
        const char* names[] = {"a", "b", "c"};
        for (int k = 0; k < 3; ++k) {
            s << ' ' << names[k];
            for (const double x : {v_[k].x, v_[k].y, v_[k].z}) {
                s << ' ';
                write_number(s, x);
            }
        }
        write_surface(s);
        s << " }";
    }

private:
    void set_geometry(const point& a, const point& b, const point& c) {
        v_[0] = a.homogenized();
        v_[1] = b.homogenized();
        v_[2] = c.homogenized();
        normal_ = ((v_[1] - v_[0]) % (v_[2] - v_[0])).unit();
        low_ = high_ = v_[0];
        for (const point& p : v_) {
            low_ = point(std::min(low_.x, p.x), std::min(low_.y, p.y), std::min(low_.z, p.z));
            high_ = point(std::max(high_.x, p.x), std::max(high_.y, p.y), std::max(high_.z, p.z));
        }
    }

    intersection find_intersection(const ray& r) const override {
        const ray_frame frame(r);
        const frame_point a = frame(v_[0]), b = frame(v_[1]), c = frame(v_[2]);
        const double e0 = edge(a, b), e1 = edge(b, c), e2 = edge(c, a);
        const bool some_negative = e0 < 0 || e1 < 0 || e2 < 0, some_positive = e0 > 0 || e1 > 0 || e2 > 0;
        if (some_negative == some_positive) return intersection::none();  // mixed, or all zero (in the plane)
        const double speed = r.direction() * normal_;
        if (speed == 0) return intersection::none();
        const double t = ((v_[0] - r.origin()) * normal_) / speed;
        if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
        return intersection::none();
    }

    point v_[3];
    vector normal_;
    point low_, high_;
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    if (const std::string problem = triangle_problem(a.homogenized(), b.homogenized(), c.homogenized()); !problem.empty())
        throw usage_error("make_triangle: " + problem);
    return std::make_unique<triangle>(a, b, c);
}

}  // namespace vl::stage02
