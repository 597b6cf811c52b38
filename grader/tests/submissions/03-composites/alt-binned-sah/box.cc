// BOX: six polygons behind one box test.
#include <cmath>
#include <ostream>

#include "geom3.hh"
#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool ordered(const geom3::triple& a, const geom3::triple& b) { return a[0] < b[0] && a[1] < b[1] && a[2] < b[2]; }

class box6 final : public rtab_composite {
public:
    box6(const geom3::triple& lo, const geom3::triple& hi) { rebuild(lo, hi); }

    std::string type_name() const override { return "BOX"; }
    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("BOX: a box is made of its six faces, insert() cannot add to it "
                          "(put the BOX and the other object in a LIST)");
    }
    void delete_all_children() override {
        throw usage_error("BOX: a box is made of its six faces, they cannot be deleted");
    }

    point min_point() const override { return geom3::as_point(lo_); }
    point max_point() const override { return geom3::as_point(hi_); }

    bool contains(const point& p) const override {
        const geom3::triple q = geom3::xyz(p.homogenized());
        return ordered(lo_, q) && ordered(q, hi_);
    }

    vector normal(const point& p) const override {
        const geom3::triple q = geom3::xyz(p.homogenized());
        // Distances to the six planes: lo x, lo y, lo z, hi x, hi y, hi z.
        int face = 0;
        double nearest = std::fabs(q[0] - lo_[0]);
        for (int k = 1; k < 6; ++k) {
            const double d = std::fabs(k < 3 ? q[k] - lo_[k] : hi_[k - 3] - q[k - 3]);
            if (d < nearest) {
                nearest = d;
                face = k;
            }
        }
        geom3::triple n{0, 0, 0};
        n[face % 3] = face < 3 ? -1 : 1;
        return vector(n[0], n[1], n[2]);
    }

    void read(scene_reader& in) override {
        geom3::triple lo = lo_, hi = hi_;
        source_location where = in.peek().where;
        auto corner = [&](geom3::triple& into, const char* what) {
            where = in.peek().where;
            const geom3::triple v = geom3::xyz(in.read_point(what).homogenized());
            if (!geom3::all_finite(v)) in.fail(where, std::string(what) + " must be a finite point");
            into = v;
        };
        std::vector<scene_reader::property> keys{{"min", [&] { corner(lo, "min of BOX"); }},
                                                 {"max", [&] { corner(hi, "max of BOX"); }}};
        add_surface_properties(keys, in, look_, "BOX");
        in.read_block("BOX", keys);
        if (!ordered(lo, hi)) in.fail(where, "BOX: min must be below max in every axis");
        rebuild(lo, hi);
    }

    void write(std::ostream& out) const override {
        out << "BOX {\n  min";
        for (double x : lo_) {
            out << ' ';
            geom3::number(out, x);
        }
        out << "\n  max";
        for (double x : hi_) {
            out << ' ';
            geom3::number(out, x);
        }
        out << "\n ";
        write_surface(out, look_);
        out << "\n}";
    }

private:
    void rebuild(const geom3::triple& lo, const geom3::triple& hi) {
        lo_ = lo;
        hi_ = hi;
        children_.clear();
        const double x0 = lo[0], y0 = lo[1], z0 = lo[2], x1 = hi[0], y1 = hi[1], z1 = hi[2];
        // Counter-clockwise seen from outside (the right-hand rule gives the outward normal).
        const std::vector<std::vector<point>> faces{
            {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}},  // -x
            {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}},  // -y
            {{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}},  // -z
            {{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}},  // +x
            {{x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}},  // +y
            {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}},  // +z
        };
        for (const auto& f : faces) {
            auto polygon = stage02::make_polygon(f);
            polygon->set_surface(look_);
            children_.push_back(std::move(polygon));
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, geom3::as_point(lo_), geom3::as_point(hi_))) return intersection::none();
        const intersection nearest = nearest_child_hit(r);
        return nearest.hit() ? nearest : intersection::composite_only(this);
    }

    geom3::triple lo_{}, hi_{};
    surface look_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    const geom3::triple a = geom3::xyz(lo.homogenized()), b = geom3::xyz(hi.homogenized());
    if (!geom3::all_finite(a) || !geom3::all_finite(b)) throw usage_error("make_box: the corners must be finite");
    if (!ordered(a, b)) throw usage_error("make_box: lo must be below hi in x, y and z");
    return std::make_unique<box6>(a, b);
}

}  // namespace vl::stage03
