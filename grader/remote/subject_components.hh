#pragma once
/// \file
/// \brief The subject's side of the calls on objects (calls_components.hh): the objects
/// the student's code made, by handle, the handlers that call their members, and the
/// stand-ins of the objects the judge lends (a test's probe inside the student's
/// composite), whose tests are calls back to the judge.
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "calls_components.hh"
#include "subject.hh"
#include "vl/object_list.hh"
#include "vl/primitive.hh"
#include "vl/rt_base_objects.hh"

namespace vl::remote {

/// \brief The objects of the subject that the judge can name. Those the judge had made
/// are owned here; an object the judge only meets as a hit (a part another object made)
/// gets a handle when it is first named, and stays its owner's.
class component_table {
public:
    /// Keeps `object` and returns its handle (0 for nullptr).
    handle add(std::unique_ptr<rtab_component> object);
    /// The object `from` takes the place of the object `into` (which is destroyed), and
    /// `from` names nothing after: a stand-in's object made again, as the judge changed
    /// its geometry.
    void adopt(handle into, handle from);
    /// The object `h`; throws protocol_error for a handle of no object.
    rtab_component& at(handle h) const;
    /// The handle of `object`, given one now if it has none; 0 for nullptr. A lent
    /// object's stand-in is named by its lent handle.
    handle name(const rtab_component* object);
    /// Hands over the object `h`, owned here, to whoever takes it (a composite it is
    /// inserted into); it keeps its handle while it lives.
    std::unique_ptr<rtab_component> take(handle h);
    /// Drops the object `h` (it is destroyed if owned here, and its children's handles
    /// with it).
    void erase(handle h);
    /// Forgets the handles of the children of `h` and theirs (they are about to go).
    void forget_parts(handle h);

private:
    /// Forgets the handles of `object`'s children and theirs (it is going).
    void forget_parts_locked(const rtab_component& object);
    mutable std::mutex mutex_;
    std::unordered_map<handle, const rtab_component*> by_handle_;
    std::unordered_map<const rtab_component*, handle> by_address_;
    std::unordered_map<handle, std::unique_ptr<rtab_component>> owned_;
};

/// The objects of this subject.
component_table& components();

/// Adds the handlers of calls_components.hh to `table`.
void add_component_handlers(std::vector<handler>& table);

/// The child an insert (or a stage's factory) names, as put by the judge's put_child():
/// nullptr, one of the subject's own objects (taken over), or a stand-in of a lent one.
std::unique_ptr<rtab_component> read_child(message_reader& in);

/// A stand-in of the judge's object `h` (lent, of type `type` as `d` describes it) that is
/// a vl::object_list, as a scene's root is: a scene in the subject whose objects are the
/// judge's.
std::unique_ptr<object_list> lent_list(handle h, std::string type, const description& d);

/// A stand-in of an object the judge made for the student's code (stage 02's factories,
/// as the subject of a later stage has them): `h` and its type and description as the
/// judge answered. It is a vl::primitive, whose surface the student's code may set.
std::unique_ptr<primitive> made_by_judge(message_reader& answer);
/// The same stand-in, for an object the subject described itself and posted
/// (calls_components::posted_bit).
std::unique_ptr<primitive> made_by_judge(handle h, std::string type, const description& d);

}  // namespace vl::remote
