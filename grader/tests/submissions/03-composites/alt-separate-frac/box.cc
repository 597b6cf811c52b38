// BOX: six polygons. After the box test, the faces are tried in the order in which the ray
// crosses their planes, and the first face hit is the nearest: no other face need be tested.
#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool finite_corner(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool strictly_less(const point& a, const point& b) { return a.x < b.x && a.y < b.y && a.z < b.z; }
double get(const point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
double get(const vector& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

class axis_box final : public rtab_composite {
public:
    axis_box(const point& lo, const point& hi) { build(lo, hi); }

    std::string type_name() const override { return "BOX"; }
    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("BOX refuses insert(): a box is made of its six faces and holds nothing else "
                          "(put the BOX and the other object in a LIST)");
    }
    void delete_all_children() override {
        throw usage_error("BOX refuses delete_all_children(): a box is made of its six faces");
    }

    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

    bool contains(const point& p) const override {
        const point q = p.homogenized();
        for (int a = 0; a < 3; ++a)
            if (!(get(lo_, a) < get(q, a) && get(q, a) < get(hi_, a))) return false;
        return true;
    }

    vector normal(const point& p) const override {
        const point q = p.homogenized();
        std::size_t nearest = 0;
        double gap = std::numeric_limits<double>::infinity();
        for (std::size_t f = 0; f < 6; ++f) {
            const double g = std::fabs(get(q, axis_[f]) - plane_[f]);
            if (g < gap) {
                gap = g;
                nearest = f;
            }
        }
        vector n(0, 0, 0);
        (axis_[nearest] == 0 ? n.x : axis_[nearest] == 1 ? n.y : n.z) = sign_[nearest];
        return n;
    }

    void read(scene_reader& in) override {
        point lo = lo_, hi = hi_;
        source_location where = in.peek().where;
        std::vector<scene_reader::property> keys{
            {"min", [&] {
                 where = in.peek().where;
                 lo = in.read_point("min of BOX").homogenized();
                 if (!finite_corner(lo)) in.fail(where, "min of BOX: not a finite point");
             }},
            {"max", [&] {
                 where = in.peek().where;
                 hi = in.read_point("max of BOX").homogenized();
                 if (!finite_corner(hi)) in.fail(where, "max of BOX: not a finite point");
             }}};
        add_surface_properties(keys, in, look_, "BOX");
        in.read_block("BOX", keys);
        if (!strictly_less(lo, hi)) in.fail(where, "BOX: min must be less than max in x, y and z");
        build(lo, hi);
    }

    void write(std::ostream& out) const override {
        const auto keep = out.precision(std::numeric_limits<double>::max_digits10);
        out << "BOX { min " << lo_.x << ' ' << lo_.y << ' ' << lo_.z << " max " << hi_.x << ' ' << hi_.y << ' '
            << hi_.z;
        out.precision(keep);
        write_surface(out, look_);
        out << " }";
    }

private:
    void build(const point& lo, const point& hi) {
        lo_ = lo.homogenized();
        hi_ = hi.homogenized();
        children_.clear();
        const point& a = lo_;
        const point& b = hi_;
        // +z, -z, +y, -y, +x, -x; each counter-clockwise seen from outside.
        const std::vector<point> faces[6] = {
            {{a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z}},
            {{a.x, a.y, a.z}, {a.x, b.y, a.z}, {b.x, b.y, a.z}, {b.x, a.y, a.z}},
            {{a.x, b.y, a.z}, {a.x, b.y, b.z}, {b.x, b.y, b.z}, {b.x, b.y, a.z}},
            {{a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, a.y, b.z}, {a.x, a.y, b.z}},
            {{b.x, a.y, a.z}, {b.x, b.y, a.z}, {b.x, b.y, b.z}, {b.x, a.y, b.z}},
            {{a.x, a.y, a.z}, {a.x, a.y, b.z}, {a.x, b.y, b.z}, {a.x, b.y, a.z}},
        };
        const int axis[6] = {2, 2, 1, 1, 0, 0};
        for (std::size_t f = 0; f < 6; ++f) {
            std::unique_ptr<primitive> face = stage02::make_polygon(faces[f]);
            face->set_surface(look_);
            children_.push_back(std::move(face));
            axis_[f] = axis[f];
            sign_[f] = f % 2 == 0 ? 1 : -1;
            plane_[f] = f % 2 == 0 ? get(hi_, axis[f]) : get(lo_, axis[f]);
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, lo_, hi_)) return intersection::none();
        // Where the ray crosses each face's plane; faces it never crosses forward come last.
        double at[6];
        std::size_t order[6] = {0, 1, 2, 3, 4, 5};
        for (std::size_t f = 0; f < 6; ++f) {
            const double d = get(r.direction(), axis_[f]);
            const double t = d != 0 ? (plane_[f] - get(r.origin(), axis_[f])) / d : NAN;
            at[f] = t > 0 ? t : std::numeric_limits<double>::infinity();
        }
        std::stable_sort(order, order + 6, [&](std::size_t x, std::size_t y) { return at[x] < at[y]; });
        for (std::size_t f : order) {
            const intersection i = children_[f]->intersect(r);
            if (i.hit()) return i;
        }
        return intersection::composite_only(this);
    }

    point lo_, hi_;
    surface look_;
    int axis_[6] = {};
    double sign_[6] = {};
    double plane_[6] = {};
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    const point a = lo.homogenized(), b = hi.homogenized();
    if (!finite_corner(a) || !finite_corner(b)) throw usage_error("make_box: both corners must be finite points");
    if (!strictly_less(a, b)) throw usage_error("make_box: lo must be less than hi in x, y and z");
    return std::make_unique<axis_box>(a, b);
}

}  // namespace vl::stage03
