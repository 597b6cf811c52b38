// Reference: the infinite plane (see assignments/02-sphere/stage_02.hh).
#include <cmath>

#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief The points p with (p - point_) . normal_ == 0.
class plane final : public shapes::plane_base {
public:
    vector normal(const point&) const override { return unit_normal_; }
    // Unbounded: min_point() and max_point() keep the default NaN_point ("no box").

private:
    void geometry_changed() override { unit_normal_ = normal_.unit(); }

    // Substitute the ray o + t d into (p - p0) . n = 0: t = ((p0 - o) . n) / (d . n).
    // A ray parallel to the plane (d . n == 0) never meets it; testing for exactly 0 is
    // enough, because a tiny d . n gives a huge t, which is a correct far hit (or a miss
    // when the numerator says the plane is behind the ray), never a NaN or an infinity.
    // A ray starting on the plane gets a numerator of round-off size: zero_t() rejects it.
    intersection find_intersection(const ray& r) const override {
        const double denominator = r.direction() * unit_normal_;
        if (denominator == 0) return intersection::none();
        const double t = ((point_ - r.origin()) * unit_normal_) / denominator;
        if (t > std::fabs(zero_t()) && std::isfinite(t)) return intersection::at(t, this);
        return intersection::none();
    }

    vector unit_normal_;  ///< normal_.unit()
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    return shapes::plane_base::make<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
