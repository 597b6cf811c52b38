// Reference: the infinite plane (see assignments/02-sphere/stage_02.hh).
#include <cmath>
#include <ostream>

#include "stage_02.hh"
#include "vl/shape_params.hh"

namespace vl::stage02 {

namespace {

/// \brief The points p with (p - point_on_plane) . normal == 0.
class plane final : public primitive {
public:
    plane(const point& point_on_plane, const vector& normal) { set_geometry(point_on_plane, normal); }

    std::string type_name() const override { return "PLANE"; }
    vector normal(const point&) const override { return unit_normal_; }
    bool contains(const point&) const override { return false; }  // a flat object has no inside
    // Unbounded: min_point() and max_point() keep the default NaN_point ("no box").

    void read(scene_reader& in) override {
        shapes::plane_params p{point_, normal_};
        read_with_surface(in, p.properties(in));
        set_geometry(p.point_on_plane, p.normal);
    }
    void write(std::ostream& s) const override {
        shapes::plane_params{point_, normal_}.write(s);
        write_surface(s);
        s << " }";
    }

private:
    void set_geometry(const point& point_on_plane, const vector& normal) {
        point_ = point_on_plane.homogenized();
        normal_ = vector(normal.x, normal.y, normal.z);
        unit_normal_ = normal_.unit();
    }

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

    point point_;          ///< as given, so write() writes what was read
    vector normal_;        ///< as given (not unit), for the same reason
    vector unit_normal_;   ///< normal_.unit()
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    if (!checks::finite(point_on_plane.homogenized()) || !checks::usable_normal(normal))
        throw usage_error("make_plane: the point must be finite and the normal a finite, non-zero vector");
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
