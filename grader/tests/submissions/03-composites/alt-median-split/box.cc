// The box: six polygons, tested as one box first.
#include <charconv>
#include <cmath>
#include <ostream>

#include "extent.hh"
#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool strictly_below(const point& a, const point& b) { return a.x < b.x && a.y < b.y && a.z < b.z; }

double coordinate(const point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

/// The point whose coordinate `axis` is `a`, `(axis + 1) % 3` is `b`, `(axis + 2) % 3` is `c`.
point cyclic(int axis, double a, double b, double c) {
    double xyz[3];
    xyz[axis] = a;
    xyz[(axis + 1) % 3] = b;
    xyz[(axis + 2) % 3] = c;
    return point(xyz[0], xyz[1], xyz[2]);
}

void put_number(std::ostream& out, double x) {
    char text[64];
    const auto result = std::to_chars(text, text + sizeof text, x);
    out.write(text, result.ptr - text);
}

class box final : public rtab_composite {
public:
    box(const point& lo, const point& hi) { make_faces(lo, hi); }

    std::string type_name() const override { return "BOX"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("a BOX consists of its six faces and cannot take other objects; "
                          "put the BOX and the other object in a LIST");
    }
    void delete_all_children() override {
        throw usage_error("a BOX consists of its six faces, which cannot be deleted");
    }

    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

    bool contains(const point& p) const override {
        const point q = p.homogenized();
        for (int axis = 0; axis < 3; ++axis) {
            const double v = coordinate(q, axis);
            if (!(v > coordinate(lo_, axis) && v < coordinate(hi_, axis))) return false;
        }
        return true;
    }

    vector normal(const point& p) const override {
        const point q = p.homogenized();
        int best_axis = 0;
        double best_sign = -1, best_distance = INFINITY;
        for (int axis = 0; axis < 3; ++axis) {
            const double to_lo = std::fabs(coordinate(q, axis) - coordinate(lo_, axis));
            const double to_hi = std::fabs(coordinate(hi_, axis) - coordinate(q, axis));
            if (to_lo < best_distance) {
                best_distance = to_lo;
                best_axis = axis;
                best_sign = -1;
            }
            if (to_hi < best_distance) {
                best_distance = to_hi;
                best_axis = axis;
                best_sign = 1;
            }
        }
        return vector(best_axis == 0 ? best_sign : 0, best_axis == 1 ? best_sign : 0, best_axis == 2 ? best_sign : 0);
    }

    void read(scene_reader& in) override {
        point lo = lo_, hi = hi_;
        surface s = surface_;
        source_location at = in.peek().where;
        std::vector<scene_reader::property> keys{
            {"min", [&] {
                 at = in.peek().where;
                 lo = in.read_point("min of BOX").homogenized();
                 if (!finite_point(lo)) in.fail(at, "the min corner of BOX must be a finite point");
             }},
            {"max", [&] {
                 at = in.peek().where;
                 hi = in.read_point("max of BOX").homogenized();
                 if (!finite_point(hi)) in.fail(at, "the max corner of BOX must be a finite point");
             }},
        };
        add_surface_properties(keys, in, s, "BOX");
        in.read_block("BOX", keys);
        if (!strictly_below(lo, hi)) in.fail(at, "the min corner of BOX must be below its max corner in x, y and z");
        surface_ = s;
        make_faces(lo, hi);
    }

    void write(std::ostream& out) const override {
        out << "BOX { min";
        for (int axis = 0; axis < 3; ++axis) {
            out << ' ';
            put_number(out, coordinate(lo_, axis));
        }
        out << " max";
        for (int axis = 0; axis < 3; ++axis) {
            out << ' ';
            put_number(out, coordinate(hi_, axis));
        }
        write_surface(out, surface_);
        out << " }";
    }

private:
    /// The faces, z first, then x, then y; each face's corners go counter-clockwise seen
    /// from outside: for the face at the high end of `axis`, the next axis then the one
    /// after it (their cross product is the axis itself).
    void make_faces(const point& lo, const point& hi) {
        lo_ = lo.homogenized();
        hi_ = hi.homogenized();
        children_.clear();
        for (int axis : {2, 0, 1}) {
            const double u0 = coordinate(lo_, (axis + 1) % 3), u1 = coordinate(hi_, (axis + 1) % 3);
            const double v0 = coordinate(lo_, (axis + 2) % 3), v1 = coordinate(hi_, (axis + 2) % 3);
            for (bool high : {true, false}) {
                const double a = high ? coordinate(hi_, axis) : coordinate(lo_, axis);
                std::vector<point> corners{cyclic(axis, a, u0, v0), cyclic(axis, a, u1, v0), cyclic(axis, a, u1, v1),
                                           cyclic(axis, a, u0, v1)};
                if (!high) std::swap(corners[1], corners[3]);  // the other way round: the normal points to -axis
                std::unique_ptr<primitive> face = stage02::make_polygon(corners);
                face->set_surface(surface_);
                children_.push_back(std::move(face));
            }
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, lo_, hi_)) return intersection::none();
        intersection best = intersection::none();
        for (const auto& face : children_) {
            const intersection i = face->intersect(r);
            if (i.nearer_than(best)) best = i;
        }
        return best.hit() ? best : intersection::composite_only(this);
    }

    point lo_, hi_;
    surface surface_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    const point a = lo.homogenized(), b = hi.homogenized();
    if (!finite_point(a) || !finite_point(b)) throw usage_error("make_box: the corners must be finite points");
    if (!strictly_below(a, b)) throw usage_error("make_box: lo must be below hi in x, y and z");
    return std::make_unique<box>(a, b);
}

}  // namespace vl::stage03
