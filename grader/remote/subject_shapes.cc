// Stage 02's contract as the subject of a later stage has it: each factory is a call to
// the judge, which makes the reference's shape and lends it (calls_components.hh). The
// student's composite holds a stand-in whose tests the judge counts; the surface the
// student's code gives it is the stand-in's, and reaches the judge with its children.
// A sphere is posted instead (calls_components::posted_bit): a fractal makes thousands.
#include <atomic>
#include <memory>
#include <vector>

#include "stage_02.hh"
#include "subject_components.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

namespace c = remote::calls_components;

/// The judge's end of this thread's connection, for the factory `what`.
remote::endpoint& judge_for(const char* what) {
    remote::endpoint* judge = remote::judge_here();
    if (judge == nullptr)
        throw remote::protocol_error(std::string(what) + " was called on a thread your code started itself: "
                                     "the grader makes shapes only on the threads the tests call on");
    return *judge;
}

std::unique_ptr<primitive> made(c::lent_op op, const remote::message_writer& args, const char* what) {
    remote::message_reader answer = judge_for(what).call(op, args, what);
    return remote::made_by_judge(answer);
}

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    remote::endpoint& judge = judge_for("make_sphere");
    // Refused here as the judge's make_sphere() would refuse it: the same check.
    shapes::sphere_base::check(center, radius);
    // What the judge's sphere will answer without being asked: its box and ball about the
    // homogenized centre (shapes::sphere_base), and the surface every primitive starts with.
    const point c = center.homogenized();
    const vector half(radius, radius, radius);
    remote::description d;  // not a composite; its surface the default one
    d.primitive = 1;
    d.min = c - half;
    d.max = c + half;
    d.ball = {c, radius};
    static std::atomic<remote::handle> last{0};
    const remote::handle h = c::lent_bit | c::posted_bit | ++last;
    judge.post(c::posted_sphere, remote::message_writer().put(h).put(center).put(radius));
    return remote::made_by_judge(h, "SPHERE", d);
}
std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    return made(c::make_lent_plane, remote::message_writer().put(point_on_plane).put(normal), "make_plane");
}
std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    return made(c::make_lent_triangle, remote::message_writer().put(a).put(b).put(c), "make_triangle");
}
std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    return made(c::make_lent_polygon, remote::message_writer().put_vector(vertices), "make_polygon");
}

}  // namespace vl::stage02
