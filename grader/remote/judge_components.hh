#pragma once
/// \file
/// \brief The judge's stand-ins for objects the subject made: a `remote_component<Base>`
/// is a `Base` (an rtab_component, or a stage's base class of one) whose members a piece
/// may override are calls to the subject's object (calls_components.hh). A test holds it
/// as it would hold the student's object. A `remote_composite<Base>` is one that holds
/// children: what a test inserts crosses to the subject (a stand-in's object itself, or
/// a lent object of the test's), and its children() mirror the subject's composite's.
///
/// An intersection that comes back names the object hit by handle; the judge finds the
/// stand-in of that handle, or the lent object, or (a part the subject's object made
/// itself) makes a stand-in now.
#include <atomic>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

#include "calls_components.hh"
#include "judge_connection.hh"
#include "vl/composite_bases.hh"
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

/// Makes an object in the subject with the student's factory `op` (its arguments `args`;
/// `what` names it for a student); its handle (0: the factory returned nullptr).
handle made_in_subject(op_id op, const message_writer& args, const char* what);

/// Records that `stand_in` stands for the subject's object `h` (until forget()).
void enter_stand_in(handle h, const rtab_component* stand_in);
void forget_stand_in(handle h);

/// \name Lent objects (calls_components.hh)
///@{
/// The handle under which the subject knows the judge's object `o` (lent_bit set), given
/// now if it has none. `root`: the lent object whose answer named `o` (a part of it: it
/// goes when its root is taken back), or 0.
handle lend(const rtab_component* o, handle root = 0);
/// Takes back `o` and every part lent under it: the subject's calls on them fail from
/// now on. The owner of a lent object calls it before the object goes.
void unlend(const rtab_component* o) noexcept;
/// What the subject's stand-in of `o` knows of it without asking.
description describe(const rtab_component& o);
/// Keeps `made`, an object the subject had the judge make, under a new lent handle until
/// the subject releases it or a composite's children take it over; its handle.
handle keep_made(std::unique_ptr<rtab_component> made);
/// As keep_made(), under the handle `h` the subject chose for it (a posted make:
/// calls_components::posted_bit); throws protocol_error for a handle without lent_bit and
/// posted_bit, or one already in use.
void keep_made_as(handle h, std::unique_ptr<rtab_component> made);
/// The handlers of the subject's calls (calls_components::lent_op), to which a stage's
/// judge adds its own (the other stages' factories) before the first test.
std::vector<handler>& judge_handlers();
/// The subject released the lent handle `h`.
void released_by_subject(handle h);
/// Adds what the student's code declared to this thread's counters.
void add_declared(const declared_counts& d);
///@}

/// \brief What every stand-in is, whatever its base: the handle of its object, and a
/// way to bring that object up to date before a call made around the stand-in.
class remote_identity {
public:
    virtual handle remote_id() const = 0;
    /// Sends the subject what changed in the stand-in since its last call.
    virtual void bring_up_to_date() const = 0;
    /// The subject's object now belongs to another of the subject's objects (a composite
    /// it was inserted into): the stand-in no longer releases it.
    virtual void given_away() = 0;

protected:
    ~remote_identity() = default;
};

/// \brief A stand-in whose children mirror the subject's object's (see remote_composite).
class mirror_node {
public:
    /// The children the stand-in holds, as its object's children() in the subject are.
    virtual std::vector<std::unique_ptr<rtab_component>>& mirrored_children() = 0;

protected:
    ~mirror_node() = default;
};

/// Makes the children of `node` (a mirror_node, the stand-in of the subject's composite
/// `h`) those of the subject's object again. `kept` holds what the test gave the composite;
/// objects taken from it that the subject's composite no longer holds go back to it.
void mirror_children(handle h, mirror_node& node, std::vector<std::unique_ptr<rtab_component>>& kept);

/// Sends `child` (nullptr, a stand-in or an object of the judge's) as the subject's
/// insert() and make_transformed() read it.
void put_child(message_writer& w, const rtab_component* child);

/// Takes back every lent object in `objects` and below them in stand-ins' children.
void unlend_all(std::vector<std::unique_ptr<rtab_component>>& objects) noexcept;

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
    void given_away() override { owned_ = false; }

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

/// \brief The stand-in of a composite of the student's: insert() and
/// delete_all_children() are the subject's object's, and children() holds what the
/// subject's object holds, in its order: the test's objects it was given, stand-ins of
/// the subject's own parts (a BOX's faces), the objects it had the judge make.
template <class Base>
class remote_composite : public remote_component<Base>, public mirror_node {
public:
    using remote_component<Base>::remote_component;
    ~remote_composite() override {
        unlend_all(this->children_);
        unlend_all(kept_);
        unlend_all(retired_);
    }

    void insert(std::unique_ptr<rtab_component> child) override {
        // A composite that takes any bounded child gets thousands of them (a BVH's budget
        // scenes) in one crossing: a lent child with a known box waits here, in the
        // mirror already, until the next call that reaches the subject's object.
        if (defers_bounded_children() && child && dynamic_cast<remote_identity*>(child.get()) == nullptr &&
            shapes::finite_box(*child) && pending_ < max_waiting) {
            this->update();
            this->children_.push_back(std::move(child));
            ++pending_;
            return;
        }
        this->sync();
        message_writer w;
        w.put(this->id());
        put_child(w, child.get());
        message_reader in;
        try {
            in = subject().call(calls_components::insert, w, "insert");
        } catch (...) {
            // Refused: the child goes, as it would have gone with the call in one process.
            if (child && dynamic_cast<remote_identity*>(child.get()) == nullptr) unlend(child.get());
            if (auto* r = dynamic_cast<remote_identity*>(child.get())) r->given_away();
            throw;
        }
        const auto count = in.get<std::uint32_t>();
        const auto last = in.get<handle>();
        in.finish();
        if (auto* r = dynamic_cast<remote_identity*>(child.get())) r->given_away();
        // The usual case, an append, without asking for every child again.
        const handle named = child == nullptr                                          ? 0
                             : dynamic_cast<const remote_identity*>(child.get()) != nullptr
                                 ? dynamic_cast<const remote_identity*>(child.get())->remote_id()
                                 : lend(child.get());
        if (child && count == this->children_.size() + 1 && last == named) {
            this->children_.push_back(std::move(child));
            return;
        }
        if (child) kept_.push_back(std::move(child));
        refresh();
    }
    void delete_all_children() override {
        this->sync();
        subject().call(calls_components::delete_all_children, message_writer().put(this->id()), "delete_all_children");
        refresh();
        // What the composite held and no longer does goes, as it would in one process.
        unlend_all(kept_);
        kept_.clear();
    }
    std::vector<std::unique_ptr<rtab_component>>& mirrored_children() override { return this->children_; }

    /// Mirrors the subject's composite's children again; `given` (may be null) is an
    /// object the test gave it outside insert() (make_transformed()'s child).
    void refresh(std::unique_ptr<rtab_component> given = nullptr) {
        if (pending_.load() != 0) send_pending();
        if (given) kept_.push_back(std::move(given));
        mirror_children(this->id(), *this, kept_);
    }

protected:
    /// Sends the children insert() kept waiting, then what update() sends.
    void sync() const final {
        this->update();
        if (pending_.load() != 0) {
            // Threads that call at once (a test's four) send them once.
            const std::lock_guard<std::mutex> lock(pending_mutex_);
            if (pending_.load() != 0) const_cast<remote_composite*>(this)->send_pending();
        }
    }
    /// What a stage's stand-in changed that the subject's object must know before its next
    /// call (a scene file's leaf size, a matrix).
    virtual void update() const {}
    /// True for a composite whose insert() takes any child with a known box (a BVH, a
    /// bounding sphere): its inserts of such children wait and cross together.
    virtual bool defers_bounded_children() const { return false; }

    /// The subject's object `again` takes the place of this stand-in's (a scene file
    /// changed what the factory made): the old object's children go with it.
    void remake(handle again) {
        // Children still waiting go to the object made again, as they came after the change.
        std::vector<std::unique_ptr<rtab_component>> waiting;
        for (std::size_t k = this->children_.size() - pending_.load(); k < this->children_.size(); ++k)
            waiting.push_back(std::move(this->children_[k]));
        this->children_.resize(this->children_.size() - waiting.size());
        pending_ = 0;
        std::vector<std::unique_ptr<rtab_component>> old = std::move(this->children_);
        this->children_.clear();
        subject().call(calls_components::adopt, message_writer().put(this->id()).put(again),
                       "the object read from a scene file");
        unlend_all(old);
        drop_retired();
        refresh();
        for (auto& w : waiting) this->children_.push_back(std::move(w));
        pending_ = waiting.size();
    }
    /// Keeps the children the stand-in holds alive, as the subject's object still holds
    /// them, while a scene file's reading clears children_ (see remake()).
    void retire_children() {
        for (auto& child : this->children_) retired_.push_back(std::move(child));
        this->children_.clear();
    }
    /// Lets the retired children go (the object that held them has gone).
    void drop_retired() {
        unlend_all(retired_);
        retired_.clear();
    }

private:
    /// The last pending_ children, inserted here but not yet in the subject: one call.
    void send_pending() {
        // pending_ goes to 0 only once the subject has them: another thread that calls
        // meanwhile waits for them at the lock in sync().
        const std::size_t n = pending_;
        message_writer w;
        w.put(this->id()).put(static_cast<std::uint32_t>(n));
        for (std::size_t k = this->children_.size() - n; k < this->children_.size(); ++k)
            put_child(w, this->children_[k].get());
        message_reader in;
        try {
            in = subject().call(calls_components::insert_each, w, "insert");
        } catch (...) {
            pending_ = 0;
            refresh();  // what the subject's object took, before it refused one
            throw;
        }
        pending_ = 0;
        const auto count = in.get<std::uint32_t>();
        const auto last = in.get<handle>();
        in.finish();
        if (count != this->children_.size() || (count != 0 && last != lend(this->children_.back().get()))) refresh();
    }
    /// The most children that wait: a crossing of a few MiB.
    static constexpr std::size_t max_waiting = 16384;
    std::atomic<std::size_t> pending_ = 0;
    mutable std::mutex pending_mutex_;
    std::vector<std::unique_ptr<rtab_component>> kept_;  ///< given to the composite, not among its children
    std::vector<std::unique_ptr<rtab_component>> retired_;  ///< held by an object about to be made again
};

}  // namespace vl::remote
