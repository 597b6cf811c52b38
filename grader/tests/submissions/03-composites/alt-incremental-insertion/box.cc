// BOX: its faces are polygons over the eight corners, tested behind one box test.
#include <cmath>
#include <cstdio>
#include <ostream>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool finite3(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool less3(const point& a, const point& b) { return a.x < b.x && a.y < b.y && a.z < b.z; }

std::string g17(double x) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

/// Corner k of a box has x from the high corner when bit 0 of k is set, y bit 1, z bit 2.
/// Each face lists its corners counter-clockwise seen from outside, with its outward normal.
struct face_of_box {
    int corner[4];
    vector outward;
};
const face_of_box faces[6] = {
    {{1, 3, 7, 5}, {1, 0, 0}},   // x high
    {{0, 4, 6, 2}, {-1, 0, 0}},  // x low
    {{2, 6, 7, 3}, {0, 1, 0}},   // y high
    {{0, 1, 5, 4}, {0, -1, 0}},  // y low
    {{4, 5, 7, 6}, {0, 0, 1}},   // z high
    {{0, 2, 3, 1}, {0, 0, -1}},  // z low
};

class polygon_box final : public rtab_composite {
public:
    polygon_box(const point& lo, const point& hi) { shape(lo, hi); }

    std::string type_name() const override { return "BOX"; }
    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("BOX cannot take other objects: a box is its six faces (put the BOX and the other object "
                          "in a LIST)");
    }
    void delete_all_children() override { throw usage_error("BOX cannot lose its six faces: they are the box"); }

    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

    bool contains(const point& p) const override {
        const point q = p.homogenized();
        return less3(lo_, q) && less3(q, hi_);
    }

    vector normal(const point& p) const override {
        const point q = p.homogenized();
        int nearest = 0;
        double gap = INFINITY;
        for (int f = 0; f < 6; ++f) {
            // The face's plane passes through its first corner; outward * (q - corner) is the
            // signed distance from it.
            const double d = std::fabs(faces[f].outward * (q - corner(faces[f].corner[0])));
            if (d < gap) {
                gap = d;
                nearest = f;
            }
        }
        return faces[nearest].outward;
    }

    void read(scene_reader& in) override {
        point lo = lo_, hi = hi_;
        source_location at = in.peek().where;
        std::vector<scene_reader::property> keys{
            {"min",
             [&] {
                 at = in.peek().where;
                 lo = in.read_point("min of BOX").homogenized();
                 if (!finite3(lo)) in.fail(at, "min of BOX is not a finite point");
             }},
            {"max",
             [&] {
                 at = in.peek().where;
                 hi = in.read_point("max of BOX").homogenized();
                 if (!finite3(hi)) in.fail(at, "max of BOX is not a finite point");
             }},
        };
        add_surface_properties(keys, in, look_, "BOX");
        in.read_block("BOX", keys);
        if (!less3(lo, hi)) in.fail(at, "BOX needs min below max in x, y and z");
        shape(lo, hi);
    }

    void write(std::ostream& out) const override {
        out << "BOX { min " << g17(lo_.x) << ' ' << g17(lo_.y) << ' ' << g17(lo_.z) << " max " << g17(hi_.x) << ' '
            << g17(hi_.y) << ' ' << g17(hi_.z);
        write_surface(out, look_);
        out << " }";
    }

private:
    point corner(int k) const { return point(k & 1 ? hi_.x : lo_.x, k & 2 ? hi_.y : lo_.y, k & 4 ? hi_.z : lo_.z); }

    void shape(const point& lo, const point& hi) {
        lo_ = lo.homogenized();
        hi_ = hi.homogenized();
        children_.clear();
        for (const face_of_box& f : faces) {
            auto polygon = stage02::make_polygon(
                {corner(f.corner[0]), corner(f.corner[1]), corner(f.corner[2]), corner(f.corner[3])});
            polygon->set_surface(look_);
            children_.push_back(std::move(polygon));
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, lo_, hi_)) return intersection::none();
        intersection nearest = intersection::none();
        for (const auto& f : children_)
            if (const intersection i = f->intersect(r); i.nearer_than(nearest)) nearest = i;
        if (nearest.hit()) return nearest;
        return intersection::composite_only(this);
    }

    point lo_, hi_;
    surface look_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    if (!finite3(lo.homogenized()) || !finite3(hi.homogenized()))
        throw usage_error("make_box: a corner is not a finite point");
    if (!less3(lo.homogenized(), hi.homogenized())) throw usage_error("make_box: lo must be below hi in x, y and z");
    return std::make_unique<polygon_box>(lo, hi);
}

}  // namespace vl::stage03
