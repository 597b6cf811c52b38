// The judge's stage 02: the contract's factories (stage_02.hh) as calls to the subject,
// and stand-ins for the shapes they make. A stand-in is the framework's base of its shape
// (shapes::sphere_base, ...), so reading a scene file and keeping the surface are the
// framework's own code, here; what the student wrote (hits, normals, boxes) is the
// subject's object's. What the judge changes (the geometry a scene file gives, a surface)
// reaches the subject's object before its next call.
#include <memory>
#include <vector>

#include "calls_02.hh"
#include "judge_components.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

using namespace vl::remote;
namespace c = calls_02;


void put(message_writer& w, const point& p) { w.put(p); }
void put(message_writer& w, const vector& v) { w.put(v); }
void put(message_writer& w, double d) { w.put(d); }
void put(message_writer& w, const std::vector<point>& vertices) { w.put_vector(vertices); }

/// \brief The stand-in of a student's shape whose framework base is `Base`.
template <class Base>
class remote_shape final : public remote_component<Base> {
public:
    /// Makes the subject's object with the student's factory `op` from `args` (which
    /// throws what that factory throws), and its stand-in of the same geometry.
    template <class... Args>
    static std::unique_ptr<primitive> make(c::op op, const char* what, const Args&... args) {
        message_writer w;
        (put(w, args), ...);
        const handle h = made_in_subject(op, w, what);
        auto s = std::make_unique<remote_shape>();
        s->set_geometry(args...);
        s->attach(h);
        s->geometry_changed_ = false;
        s->sent_surface_ = &s->surf();
        return s;
    }

private:
    /// The subject's object of this geometry, made by the student's factory.
    handle make_in_subject() const;

    void geometry_changed() override { geometry_changed_ = true; }
    void sync() const override {
        if (geometry_changed_) {
            // A scene file gave the geometry: the student's factory makes the object again,
            // and it takes the old one's place and handle.
            const handle again = make_in_subject();
            subject().call(c::adopt, message_writer().put(this->id()).put(again), "the object read from a scene file");
            geometry_changed_ = false;
            sent_surface_ = nullptr;
        }
        if (&this->surf() != sent_surface_) {
            subject().call(c::set_surface, message_writer().put(this->id()).put(this->surf()), "set_surface");
            sent_surface_ = &this->surf();
        }
    }
    mutable bool geometry_changed_ = false;
    mutable const surface* sent_surface_ = nullptr;  ///< the surface the subject's object has (surfaces are shared)
};

template <>
handle remote_shape<shapes::sphere_base>::make_in_subject() const {
    return made_in_subject(c::make_sphere, message_writer().put(center_).put(radius_), "make_sphere");
}
template <>
handle remote_shape<shapes::plane_base>::make_in_subject() const {
    return made_in_subject(c::make_plane, message_writer().put(point_).put(normal_), "make_plane");
}
template <>
handle remote_shape<shapes::triangle_base>::make_in_subject() const {
    return made_in_subject(c::make_triangle, message_writer().put(a_).put(b_).put(c_), "make_triangle");
}
template <>
handle remote_shape<shapes::polygon_base>::make_in_subject() const {
    return made_in_subject(c::make_polygon, message_writer().put_vector(vertices_), "make_polygon");
}

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    return remote_shape<shapes::sphere_base>::make(c::make_sphere, "make_sphere", center, radius);
}
std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    return remote_shape<shapes::plane_base>::make(c::make_plane, "make_plane", point_on_plane, normal);
}
std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    return remote_shape<shapes::triangle_base>::make(c::make_triangle, "make_triangle", a, b, c);
}
std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    return remote_shape<shapes::polygon_base>::make(c::make_polygon, "make_polygon", vertices);
}

}  // namespace vl::stage02
