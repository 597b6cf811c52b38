// The triangle: a flat_loop (flat.hh) of three vertices.
#include <cmath>
#include <ostream>
#include <string>

#include "flat.hh"
#include "write_number.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

std::string triangle_problem(const point& a, const point& b, const point& c) {
    if (!finite(a) || !finite(b) || !finite(c)) return "every vertex must be a finite point (w not 0)";
    const vector ab = b - a, ac = c - a;
    if (!((ab % ac).length() > 1e-12 * ab.length() * ac.length()))
        return "its vertices a, b and c are on one line (or two coincide): it has no area";
    return "";
}

class triangle final : public flat_loop {
public:
    triangle(const point& a, const point& b, const point& c) { set(a, b, c); }

    std::string type_name() const override { return "TRIANGLE"; }

    void read(scene_reader& in) override {
        const source_location where = in.peek().where;
        point a = loop()[0], b = loop()[1], c = loop()[2];
        read_with_surface(in, {{"a", [&] { a = in.read_point("vertex a of TRIANGLE").homogenized(); }},
                               {"b", [&] { b = in.read_point("vertex b of TRIANGLE").homogenized(); }},
                               {"c", [&] { c = in.read_point("vertex c of TRIANGLE").homogenized(); }}});
        if (const std::string problem = triangle_problem(a, b, c); !problem.empty())
            in.fail(where, "this TRIANGLE is not a triangle: " + problem);
        set(a, b, c);
    }
    void write(std::ostream& s) const override {
        s << "TRIANGLE { a ";
        put(s, loop()[0], " ");
        s << " b ";
        put(s, loop()[1], " ");
        s << " c ";
        put(s, loop()[2], " ");
        write_surface(s);
        s << " }";
    }

private:
    void set(const point& a, const point& b, const point& c) { set_loop({a, b, c}, (b - a) % (c - a)); }
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    const point p = a.homogenized(), q = b.homogenized(), s = c.homogenized();
    if (const std::string problem = triangle_problem(p, q, s); !problem.empty()) throw usage_error("make_triangle: " + problem);
    return std::make_unique<triangle>(p, q, s);
}

}  // namespace vl::stage02
