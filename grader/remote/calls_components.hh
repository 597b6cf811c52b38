#pragma once
/// \file
/// \brief The calls on a ray-traceable object (vl::rtab_component) across the
/// connection, for every stage whose pieces are objects: one operation per virtual member
/// a piece may override. The first argument is always the object's handle.
///
/// An intersection crosses as its t and the object hit, named by handle: an object is
/// never named by its address, so nothing either end sends is ever used as a pointer.
///
/// **Lent objects.** A test may put an object of its own (a probe, a stage's reference
/// shape) into a composite of the student's. The object stays in the judge; the subject
/// gets a stand-in that answers its box, ball, type and surface from what was sent with
/// it, and turns intersect(), normal(), contains() and write() into calls back to the
/// judge (the `lent_*` operations below, which the judge serves). So every test of a lent
/// object is counted by the judge, in its own counters. A lent object's handle has
/// `lent_bit` set; the subject's own objects' handles never do.
///
/// **Declared counts.** The answer to intersect and intersect_each ends with what the
/// student's code counted in the subject meanwhile (its bounding-volume tests, and its
/// intersect() calls on objects of its own), less the calls on lent objects and the call
/// itself, which the judge counts. The judge adds them to its counters: they are what the
/// student's code declares, as vl::count_bounding_volume_tests() always was, and only ever
/// add to the judge's own counts.
#include "channel.hh"
#include "vl/primitive.hh"
#include "vl/stats.hh"

namespace vl::remote::calls_components {

/// Operation numbers from here up are the components'; a stage's own calls stay below.
inline constexpr op_id first = 128;

enum op : op_id {
    intersect = first,  ///< ray -> double t, handle of the object hit (0: none)
    normal,             ///< point -> vector
    contains,           ///< point -> bool
    min_point,          ///< -> point
    max_point,          ///< -> point
    bounding_ball,      ///< -> point centre, double radius
    zero_t,             ///< -> double
    type_name,          ///< -> string
    write,              ///< -> string: what write() wrote
    surface_values,     ///< -> color clr, double kdr, ksr, kdt, kst, n, ior
    intersect_each,     ///< (no object first) vector of handles, vector of rays -> per ray, per object: double t, handle hit
    insert,             ///< composite, child (see child_kind) -> nothing: the student's insert()
    delete_all_children,  ///< composite -> nothing
    children_tree,      ///< composite -> u32 how many children, they and theirs in pre-order (vector of tree_entry), vector of surface
    adopt,              ///< handle into, handle from: the object `from` takes the place of `into` (made again)
    insert_each,        ///< composite, u32 n, n children -> as insert: the student's insert() of each in turn
    end,
};

/// The operations the judge serves for the subject: a lent object's members (its handle
/// first), and the other stages' factories the student's code calls (stage_02.hh's).
enum lent_op : op_id {
    lent_intersect = 192,  ///< ray -> double t, handle hit, u8 1 and the type and description of a lent object hit (else 0)
    lent_normal,           ///< point -> vector
    lent_contains,         ///< point -> bool
    lent_write,            ///< -> string
    lent_describe,         ///< -> description (for a lent object the subject first meets as a hit)
    make_lent_sphere,      ///< (no object first) point, double -> handle, description
    make_lent_plane,       ///< point, vector -> handle, description
    make_lent_triangle,    ///< point, point, point -> handle, description
    make_lent_polygon,     ///< vector of points -> handle, description
    posted_sphere,         ///< (posted: no answer) handle chosen by the subject, point, double
};

/// The handle of a lent object has this bit set.
inline constexpr handle lent_bit = handle{1} << 63;

/// \brief A sphere the student's code makes is posted, not called.
///
/// A FRACSPH of depth 7 makes 117 187 spheres, and its code reads each one's box as soon
/// as it has made it. So make_sphere() in the subject checks its arguments as the
/// framework's shapes::sphere_base::check() does, gives the sphere a handle of its own
/// choosing (lent_bit and posted_bit set: the judge's own handles never have posted_bit),
/// knows its box and ball (centre, radius) and the default surface as the judge's sphere
/// will, and posts `posted_sphere`: the judge makes the reference's sphere under that
/// handle before it reads anything the subject sends after. A handle posted twice, or
/// one without both bits, breaks the connection.
inline constexpr handle posted_bit = handle{1} << 62;

/// What the subject's stand-in of a lent object knows of it without asking.
struct description {
    std::uint8_t composite = 0;  ///< 1 for an rtab_composite
    std::uint8_t primitive = 0;  ///< 1 for a vl::primitive the subject may set a surface on
    point min, max;
    rtab_component::ball ball;
    surface surf;  ///< its surface getters' values, zero_t among them
};

/// How a child crosses with insert (and make_transformed): none (nullptr), one of the
/// subject's objects (its handle: the subject's composite takes it over), or a lent one
/// (its handle, then its type name and description).
enum class child_kind : std::uint8_t { none = 0, own = 1, lent = 2 };

/// One object of a children_tree answer: the object, whether it is a composite, how many
/// children of its own follow it, and for a lent primitive the surface the subject set
/// (an index into the answer's list of surfaces, which primitives share).
struct tree_entry {
    handle object = 0;
    std::uint8_t composite = 0;
    std::uint8_t has_surface = 0;
    std::uint32_t children = 0;
    std::uint32_t surface_index = 0;
};

/// The most entries one children_tree answers with.
inline constexpr std::size_t max_tree = 1 << 18;

/// The most objects the subject may have the judge make (stage 02's factories).
inline constexpr std::size_t max_made = 1 << 20;

/// What the student's code counted: vl::detail::tallies, crossing as bytes.
using declared_counts = detail::tallies;

/// Every operation number is below this: the size of a handler table.
inline constexpr op_id table_size = 256;

/// The most objects, and the most rays, one intersect_each asks (the answer must fit a frame).
inline constexpr std::size_t max_batch = 1 << 16;

/// The longest text write() may answer with.
inline constexpr std::size_t max_written_bytes = 1 << 20;

}  // namespace vl::remote::calls_components

namespace vl::remote {
using calls_components::child_kind;
using calls_components::declared_counts;
using calls_components::description;
using calls_components::lent_bit;
using calls_components::tree_entry;
}  // namespace vl::remote
