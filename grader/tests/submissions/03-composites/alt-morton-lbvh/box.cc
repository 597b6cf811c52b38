// The box of six polygons. Its eight corners are numbered by three bits (bit a set: the
// high end of axis a); each face holds one bit fixed and walks the other two in Gray-code
// order, which goes once round the face's rectangle.
#include <cmath>
#include <limits>
#include <ostream>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/error.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool below(const point& a, const point& b) { return a.x < b.x && a.y < b.y && a.z < b.z; }

double axis_of(const point& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }

/// The 2-bit Gray code: 00, 01, 11, 10, each step changes one bit, so the four corners
/// it picks on a face are visited in order round its rectangle.
constexpr unsigned gray[4] = {0b00, 0b01, 0b11, 0b10};

class box final : public rtab_composite {
public:
    box(const point& lo, const point& hi) { set_geometry(lo, hi); }

    std::string type_name() const override { return "BOX"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("BOX is made of its six faces and takes no other object: insert() cannot add to it"
                          " (put the BOX and the other object in a LIST)");
    }
    void delete_all_children() override {
        throw usage_error("BOX: its six faces are the box, delete_all_children() cannot remove them");
    }

    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

    bool contains(const point& p) const override {
        for (int a = 0; a < 3; ++a) {
            const double x = axis_of(p, a);
            if (!(axis_of(lo_, a) < x && x < axis_of(hi_, a))) return false;
        }
        return true;
    }

    vector normal(const point& p) const override {
        int best_axis = 0;
        double best_sign = -1, best_gap = std::numeric_limits<double>::infinity();
        for (int a = 0; a < 3; ++a) {
            const double x = axis_of(p, a);
            const double to_lo = std::fabs(x - axis_of(lo_, a)), to_hi = std::fabs(axis_of(hi_, a) - x);
            if (to_lo < best_gap) {
                best_gap = to_lo;
                best_axis = a;
                best_sign = -1;
            }
            if (to_hi < best_gap) {
                best_gap = to_hi;
                best_axis = a;
                best_sign = 1;
            }
        }
        double n[3] = {0, 0, 0};
        n[best_axis] = best_sign;
        return vector(n[0], n[1], n[2]);
    }

    void read(scene_reader& in) override {
        point lo = lo_, hi = hi_;
        source_location where = in.peek().where;
        std::vector<scene_reader::property> properties{
            {"min", [&] {
                 where = in.peek().where;
                 lo = in.read_point("min of BOX").homogenized();
                 if (!finite(lo)) in.fail(where, "min of BOX must be a finite point (w not 0)");
             }},
            {"max", [&] {
                 where = in.peek().where;
                 hi = in.read_point("max of BOX").homogenized();
                 if (!finite(hi)) in.fail(where, "max of BOX must be a finite point (w not 0)");
             }}};
        add_surface_properties(properties, in, surface_, "BOX");
        in.read_block("BOX", properties);
        if (!below(lo, hi)) in.fail(where, "min of BOX must be below max in x, y and z (a box has volume)");
        set_geometry(lo, hi);
    }

    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "BOX { min " << lo_.x << ' ' << lo_.y << ' ' << lo_.z << " max " << hi_.x << ' ' << hi_.y << ' '
          << hi_.z;
        s.precision(old_precision);
        write_surface(s, surface_);
        s << " }";
    }

private:
    /// Corner `bits` of the box: bit a chooses the high end of axis a.
    point corner(unsigned bits) const {
        return point((bits & 1u) ? hi_.x : lo_.x, (bits & 2u) ? hi_.y : lo_.y, (bits & 4u) ? hi_.z : lo_.z);
    }

    void set_geometry(const point& lo, const point& hi) {
        lo_ = lo.homogenized();
        hi_ = hi.homogenized();
        children_.clear();
        for (unsigned a = 0; a < 3; ++a) {
            // u and v follow a cyclically, so u x v points along +a.
            const unsigned u = (a + 1) % 3, v = (a + 2) % 3;
            for (unsigned high = 0; high < 2; ++high) {
                std::vector<point> corners;
                for (unsigned step = 0; step < 4; ++step) {
                    // The Gray walk (u first, then v) turns counter-clockwise seen from +a:
                    // right for the high face; the low face, seen from -a, walks it backwards.
                    const unsigned g = gray[high ? step : 3 - step];
                    const unsigned bits = (high << a) | ((g & 1u) << u) | (((g >> 1) & 1u) << v);
                    corners.push_back(corner(bits));
                }
                auto face = stage02::make_polygon(std::move(corners));
                face->set_surface(surface_);
                children_.push_back(std::move(face));
            }
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, lo_, hi_)) return intersection::none();
        intersection nearest = intersection::none();
        for (const auto& face : children_) {
            const intersection i = face->intersect(r);
            if (i.nearer_than(nearest)) nearest = i;
        }
        return nearest.hit() ? nearest : intersection::composite_only(this);
    }

    point lo_, hi_;
    surface surface_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    if (!finite(lo.homogenized()) || !finite(hi.homogenized()))
        throw usage_error("make_box: both corners must be finite points");
    if (!below(lo.homogenized(), hi.homogenized()))
        throw usage_error("make_box: lo must be below hi in x, y and z (a box has volume)");
    return std::make_unique<box>(lo, hi);
}

}  // namespace vl::stage03
