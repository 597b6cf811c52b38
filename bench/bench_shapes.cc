#include "bench_shapes.hh"

#include <cmath>

namespace bench {

namespace {

// Geometric ray-sphere test, enough to give the call realistic work.
vl::intersection sphere_hit(const vl::ray& r, const vl::point& c, double radius, const vl::rtab_component* self) {
    const vl::vector oc = r.origin() - c;
    const double b = oc * r.direction();
    const double disc = b * b - (oc * oc - radius * radius);
    if (disc < 0) return vl::intersection::none();
    const double t = -b - std::sqrt(disc);
    return t > 1e-6 ? vl::intersection::at(t, self) : vl::intersection::none();
}

class counted_sphere final : public vl::rtab_component {
public:
    counted_sphere(vl::point c, double r) : c_(c), r_(r) {}
    std::string type_name() const override { return "SPHERE"; }

private:
    vl::intersection find_intersection(const vl::ray& r) const override { return sphere_hit(r, c_, r_, this); }
    vl::point c_;
    double r_;
};

class uncounted_sphere final : public uncounted_base {
public:
    uncounted_sphere(vl::point c, double r) : c_(c), r_(r) {}

private:
    vl::intersection find_intersection(const vl::ray& r) const override {
        // The object pointer only marks a hit here; it is never dereferenced.
        return sphere_hit(r, c_, r_, reinterpret_cast<const vl::rtab_component*>(this));
    }
    vl::point c_;
    double r_;
};

}  // namespace

uncounted_base::~uncounted_base() = default;

std::unique_ptr<vl::rtab_component> make_counted_sphere(vl::point center, double radius) {
    return std::make_unique<counted_sphere>(center, radius);
}

std::unique_ptr<uncounted_base> make_uncounted_sphere(vl::point center, double radius) {
    return std::make_unique<uncounted_sphere>(center, radius);
}

}  // namespace bench
