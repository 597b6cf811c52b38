#pragma once
/// \file
/// \brief The subject's side of the calls on objects (calls_components.hh): the objects
/// the student's code made, by handle, and the handlers that call their members.
#include <map>
#include <memory>
#include <mutex>

#include "subject.hh"
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
    /// The handle of `object`, given one now if it has none; 0 for nullptr.
    handle name(const rtab_component* object);
    /// Drops the object `h` (it is destroyed if owned here).
    void erase(handle h);

private:
    mutable std::mutex mutex_;
    std::map<handle, const rtab_component*> by_handle_;
    std::map<const rtab_component*, handle> by_address_;
    std::map<handle, std::unique_ptr<rtab_component>> owned_;
};

/// The objects of this subject.
component_table& components();

/// Adds the handlers of calls_components.hh to `table`.
void add_component_handlers(std::vector<handler>& table);

}  // namespace vl::remote
