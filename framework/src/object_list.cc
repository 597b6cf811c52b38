#include "vl/object_list.hh"

#include "vl/scene_reader.hh"

namespace vl {

void object_list::read(scene_reader& in) {
    in.read_children(*this);
}

}  // namespace vl
