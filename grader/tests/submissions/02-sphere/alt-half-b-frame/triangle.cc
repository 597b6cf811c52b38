// The triangle: inside or outside is decided by three edge functions in the ray's own
// frame (ray_frame.hh), so triangles of a mesh leave no gap; t comes from the plane.
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "numbers.hh"
#include "ray_frame.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class triangle final : public shapes::triangle_base {
public:
    triangle(const point& a, const point& b, const point& c) : triangle_base(a, b, c) { geometry_changed(); }

    vector normal(const point&) const override { return normal_; }
    point min_point() const override { return low_; }
    point max_point() const override { return high_; }

    void write(std::ostream& s) const override {
        s << "TRIANGLE {";
        const char* names[] = {"a", "b", "c"};
        const point* v[] = {&a_, &b_, &c_};
        for (int k = 0; k < 3; ++k) {
            s << ' ' << names[k];
            for (const double x : {v[k]->x, v[k]->y, v[k]->z}) {
                s << ' ';
                write_number(s, x);
            }
        }
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
        normal_ = ((b_ - a_) % (c_ - a_)).unit();
        low_ = high_ = a_;
        for (const point& p : {a_, b_, c_}) {
            low_ = point(std::min(low_.x, p.x), std::min(low_.y, p.y), std::min(low_.z, p.z));
            high_ = point(std::max(high_.x, p.x), std::max(high_.y, p.y), std::max(high_.z, p.z));
        }
    }

    intersection find_intersection(const ray& r) const override {
        const ray_frame frame(r);
        const frame_point a = frame(a_), b = frame(b_), c = frame(c_);
        const double e0 = edge(a, b), e1 = edge(b, c), e2 = edge(c, a);
        const bool some_negative = e0 < 0 || e1 < 0 || e2 < 0, some_positive = e0 > 0 || e1 > 0 || e2 > 0;
        if (some_negative == some_positive) return intersection::none();  // mixed, or all zero (in the plane)
        const double speed = r.direction() * normal_;
        if (speed == 0) return intersection::none();
        const double t = ((a_ - r.origin()) * normal_) / speed;
        if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
        return intersection::none();
    }

    vector normal_;
    point low_, high_;
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    shapes::triangle_base::check(a, b, c);
    return std::make_unique<triangle>(a, b, c);
}

}  // namespace vl::stage02
