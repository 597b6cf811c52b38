// Reference: the box of six polygons (see assignments/03-composites/stage_03.hh).
#include <cmath>
#include <limits>
#include <ostream>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"
#include "vl/shape_params.hh"

namespace vl::stage03 {

namespace {

/// \brief An axis-aligned box made of its six faces, tested as a box first.
class box final : public rtab_composite {
public:
    box(const point& lo, const point& hi) { set_geometry(lo, hi); }

    std::string type_name() const override { return "BOX"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("BOX is made of its six faces: insert() cannot add to it"
                          " (put the BOX and the other object in a LIST)");
    }
    void delete_all_children() override {
        throw usage_error("BOX is made of its six faces: they cannot be deleted");
    }

    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

    bool contains(const point& p) const override {
        const point q = p.homogenized();
        return lo_.x < q.x && q.x < hi_.x && lo_.y < q.y && q.y < hi_.y && lo_.z < q.z && q.z < hi_.z;
    }

    vector normal(const point& p) const override {
        // The face whose plane is nearest to p.
        const point q = p.homogenized();
        const double distance[6] = {q.x - lo_.x, hi_.x - q.x, q.y - lo_.y, hi_.y - q.y, q.z - lo_.z, hi_.z - q.z};
        static const vector outward[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
        int nearest = 0;
        for (int k = 1; k < 6; ++k)
            if (std::fabs(distance[k]) < std::fabs(distance[nearest])) nearest = k;
        return outward[nearest];
    }

    void read(scene_reader& in) override {
        shapes::box_params p{lo_, hi_};
        source_location where;
        std::vector<scene_reader::property> properties = p.properties(in, where);
        add_surface_properties(properties, in, surface_, "BOX");
        in.read_block("BOX", properties);
        if (!checks::below(p.lo, p.hi))
            in.fail(where, "min of BOX must be below max in x, y and z (a box has volume)");
        set_geometry(p.lo, p.hi);
    }

    void write(std::ostream& s) const override {
        shapes::box_params{lo_, hi_}.write(s);
        write_surface(s, surface_);
        s << " }";
    }

private:
    void set_geometry(const point& lo, const point& hi) {
        lo_ = lo.homogenized();
        hi_ = hi.homogenized();
        children_.clear();
        // The eight corners; corner(i, j, k) takes x, y, z from hi when i, j, k is 1.
        auto c = [&](int i, int j, int k) { return point(i ? hi_.x : lo_.x, j ? hi_.y : lo_.y, k ? hi_.z : lo_.z); };
        // Each face counter-clockwise seen from outside, so its normal points out.
        const point faces[6][4] = {
            {c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)},  // x = lo, normal -x
            {c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)},  // x = hi, normal +x
            {c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)},  // y = lo, normal -y
            {c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)},  // y = hi, normal +y
            {c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)},  // z = lo, normal -z
            {c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)},  // z = hi, normal +z
        };
        for (const auto& f : faces) {
            std::unique_ptr<primitive> face = stage02::make_polygon({f[0], f[1], f[2], f[3]});
            face->set_surface(surface_);
            children_.push_back(std::move(face));
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, lo_, hi_)) return intersection::none();
        const intersection nearest = nearest_child_hit(r);
        return nearest.hit() ? nearest : intersection::composite_only(this);
    }

    point lo_, hi_;
    surface surface_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    if (!checks::finite(lo.homogenized()) || !checks::finite(hi.homogenized()))
        throw usage_error("make_box: both corners must be finite points");
    if (!checks::below(lo.homogenized(), hi.homogenized()))
        throw usage_error("make_box: lo must be below hi in x, y and z (a box has volume)");
    return std::make_unique<box>(lo, hi);
}

}  // namespace vl::stage03
