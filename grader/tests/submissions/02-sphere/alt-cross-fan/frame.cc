#include "frame.hh"

#include <cmath>

namespace vl::stage02 {

namespace {

// Edge function of p -> q at the origin; exactly minus that of q -> p.
double edge(const in_frame& p, const in_frame& q) { return p.x * q.y - p.y * q.x; }

}  // namespace

frame::frame(const ray& r) : o_(r.origin()), z_(r.direction()) {
    const double ax = std::fabs(z_.x), ay = std::fabs(z_.y), az = std::fabs(z_.z);
    const vector axis = ax <= ay && ax <= az ? vector(1, 0, 0) : ay <= az ? vector(0, 1, 0) : vector(0, 0, 1);
    x_ = (axis - (axis * z_) * z_).unit();
    y_ = z_ % x_;
}

in_frame frame::operator()(const point& p) const {
    const vector q = p - o_;
    return {q * x_, q * y_, q * z_};
}

std::optional<double> crossing(const in_frame& a, const in_frame& b, const in_frame& c) {
    const double ea = edge(b, c), eb = edge(c, a), ec = edge(a, b);
    const double lo = std::fmin(ea, std::fmin(eb, ec)), hi = std::fmax(ea, std::fmax(eb, ec));
    if (lo < 0 && hi > 0) return std::nullopt;
    const double sum = ea + eb + ec;
    if (sum == 0) return std::nullopt;
    return (ea * a.z + eb * b.z + ec * c.z) / sum;
}

}  // namespace vl::stage02
