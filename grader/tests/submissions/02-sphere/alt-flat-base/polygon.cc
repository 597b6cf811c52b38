// The convex polygon: a flat_loop (flat.hh) of its vertices, with Newell's normal.
#include <algorithm>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "flat.hh"
#include "vl/convex_polygon.hh"
#include "write_number.hh"

namespace vl::stage02 {

namespace {

class polygon final : public flat_loop {
public:
    explicit polygon(std::vector<point> vertices) { set(std::move(vertices)); }

    std::string type_name() const override { return "POLYGON"; }

    void read(scene_reader& in) override {
        std::vector<point> vertices = loop();
        read_with_surface(in, {{"vertices", [&] {
                                    if (in.peek().text != "(")
                                        in.fail_expected("'(' to start a vertex of POLYGON (each vertex is written (x, y, z))");
                                    std::vector<source_location> where;
                                    vertices.clear();
                                    while (in.peek().type == token::kind::punct && in.peek().text == "(") {
                                        where.push_back(in.peek().where);
                                        vertices.push_back(in.read_point("vertex of POLYGON").homogenized());
                                    }
                                    if (const auto problem = find_polygon_problem(vertices)) {
                                        const std::size_t at = std::min(problem->vertex, where.size() - 1);
                                        in.fail(where[at], "this POLYGON is not convex and planar: " + problem->message);
                                    }
                                }}});
        set(std::move(vertices));
    }
    void write(std::ostream& s) const override {
        s << "POLYGON { vertices";
        for (const point& p : loop()) {
            s << " (";
            put(s, p, ", ");
            s << ')';
        }
        write_surface(s);
        s << " }";
    }

private:
    void set(std::vector<point> vertices) {
        const vector n = newell_normal(vertices, centroid_of(vertices));
        set_loop(std::move(vertices), n);
    }
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    for (point& p : vertices) p = p.homogenized();
    if (const auto problem = find_polygon_problem(vertices)) throw usage_error("make_polygon: " + problem->message);
    return std::make_unique<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
