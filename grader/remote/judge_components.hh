#pragma once
/// \file
/// \brief The judge's stand-ins for objects the subject made: a `remote_component<Base>`
/// is a `Base` (an rtab_component, or a stage's base class of one) whose members a piece
/// may override are calls to the subject's object (calls_components.hh). A test holds it
/// as it would hold the student's object.
///
/// An intersection that comes back names the object hit by handle; the judge finds the
/// stand-in of that handle, or (a part the subject's object made itself) makes one now.
#include <ostream>
#include <string>

#include "calls_components.hh"
#include "judge_connection.hh"
#include "vl/rt_base_objects.hh"

namespace vl::remote {

/// \brief The calls, one function each (judge_components.cc).
namespace component_calls {
intersection intersect(handle h, const ray& r);
vector normal(handle h, const point& p);
bool contains(handle h, const point& p);
point min_point(handle h);
point max_point(handle h);
rtab_component::ball bounding_ball(handle h);
double zero_t(handle h);
std::string type_name(handle h);
std::string written(handle h);
/// clr, kdr, ksr, kdt, kst, n, ior.
struct surface_values {
    color clr;
    double kdr, ksr, kdt, kst, n, ior;
};
surface_values surface_of(handle h);
}  // namespace component_calls

/// Records that `stand_in` stands for the subject's object `h` (until forget()).
void enter_stand_in(handle h, const rtab_component* stand_in);
void forget_stand_in(handle h);

/// \brief What every stand-in is, whatever its base: the handle of its object, and a
/// way to bring that object up to date before a call made around the stand-in.
class remote_identity {
public:
    virtual handle remote_id() const = 0;
    /// Sends the subject what changed in the stand-in since its last call.
    virtual void bring_up_to_date() const = 0;

protected:
    ~remote_identity() = default;
};

/// \brief A `Base` whose overridable members are the subject's object's.
template <class Base>
class remote_component : public Base, public remote_identity {
public:
    using Base::Base;
    ~remote_component() override {
        if (handle_ != 0) {
            forget_stand_in(handle_);
            if (owned_) subject().release(handle_);
        }
    }
    /// Makes this the stand-in of the subject's object `h`; `owned`: releasing it is the
    /// judge's (it had the object made), not the subject's.
    void attach(handle h, bool owned = true) {
        handle_ = h;
        owned_ = owned;
        enter_stand_in(h, this);
    }
    handle id() const { return handle_; }
    handle remote_id() const override { return handle_; }
    void bring_up_to_date() const override { sync(); }

    vector normal(const point& p) const override { return (sync(), component_calls::normal(handle_, p)); }
    bool contains(const point& p) const override { return (sync(), component_calls::contains(handle_, p)); }
    point min_point() const override { return (sync(), component_calls::min_point(handle_)); }
    point max_point() const override { return (sync(), component_calls::max_point(handle_)); }
    rtab_component::ball bounding_ball() const override { return (sync(), component_calls::bounding_ball(handle_)); }
    double zero_t() const override { return (sync(), component_calls::zero_t(handle_)); }
    std::string type_name() const override { return (sync(), component_calls::type_name(handle_)); }
    void write(std::ostream& s) const override {
        sync();
        s << component_calls::written(handle_);
    }
    color clr() const override { return (sync(), component_calls::surface_of(handle_).clr); }
    double kdr() const override { return (sync(), component_calls::surface_of(handle_).kdr); }
    double ksr() const override { return (sync(), component_calls::surface_of(handle_).ksr); }
    double kdt() const override { return (sync(), component_calls::surface_of(handle_).kdt); }
    double kst() const override { return (sync(), component_calls::surface_of(handle_).kst); }
    double n() const override { return (sync(), component_calls::surface_of(handle_).n); }
    double ior() const override { return (sync(), component_calls::surface_of(handle_).ior); }

protected:
    /// Brings the subject's object up to date with what the judge changed in this one
    /// since the last call (a stage's stand-in reads scene text here, for one).
    virtual void sync() const {}

private:
    intersection find_intersection(const ray& r) const override {
        sync();
        return component_calls::intersect(handle_, r);
    }
    handle handle_ = 0;
    bool owned_ = true;
};

}  // namespace vl::remote
