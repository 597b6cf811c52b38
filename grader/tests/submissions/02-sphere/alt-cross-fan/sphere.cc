// The sphere. The ray's distance from the centre is |f x d| (f from the centre to the
// origin): no difference of two large, nearly equal squares, so a small sphere far away
// keeps its digits. The root that does not cancel comes first, the other from c / it.
#include <cmath>
#include <ostream>

#include "stage_02.hh"
#include "text.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class sphere final : public shapes::sphere_base {
public:
    sphere(const point& center, double radius) : sphere_base(center, radius) {}

    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override { return (p - center_).length() < radius_; }
    point min_point() const override { return {center_.x - radius_, center_.y - radius_, center_.z - radius_}; }
    point max_point() const override { return {center_.x + radius_, center_.y + radius_, center_.z + radius_}; }

    void write(std::ostream& s) const override {
        s << "SPHERE { center " << number{center_.x} << ' ' << number{center_.y} << ' ' << number{center_.z}
          << " radius " << number{radius_};
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const vector f = r.origin() - center_, d = r.direction();
        const vector cross = f % d;
        const double distance2 = cross * cross;  // squared distance of the ray's line from the centre
        const double rr = radius_ * radius_;
        if (distance2 > rr) return intersection::none();
        const double h = std::sqrt(rr - distance2);
        const double b = f * d;
        const double c = f * f - rr;
        const double q = b > 0 ? -b - h : -b + h;  // the root of larger magnitude
        if (q == 0) return intersection::none();
        const double other = c / q;
        const double first = q < other ? q : other, second = q < other ? other : q;
        const double eps = std::fabs(zero_t());
        if (first > eps) return intersection::at(first, this);
        if (second > eps) return intersection::at(second, this);
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    shapes::sphere_base::check(center, radius);
    return std::make_unique<sphere>(center, radius);
}

}  // namespace vl::stage02
