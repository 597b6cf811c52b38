#pragma once
/// \file
/// \brief The shells of stage 03's composites: everything about a BOUNDSPH, FRACSPH, BOX,
/// TRANSFORM and BVH that is not its algorithm. Each base class here holds a composite's
/// values, names its type, reads and writes it (through vl/shape_params.hh), makes the
/// checks its factory makes and refuses what it refuses; the class that derives from it
/// (in assignments/03-composites, or the reference) writes the algorithm: how a ray is
/// tested, how the bound grows, how the tree is built, what the box and normal are.
///
/// The error messages of these checks are part of stage 03's contract
/// (assignments/03-composites/stage_03.hh): every implementation refuses the same things
/// with the same words. A derived class may still override any virtual member here.
///
/// The framework depends on no stage: where a shell needs a stage's code (a TRANSFORM's
/// steps and inverse are stage 01's), the derived class passes the functions in.

#include <atomic>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <string>

#include "vl/primitive.hh"
#include "vl/rt_base_objects.hh"
#include "vl/shape_params.hh"

namespace vl::shapes {

/// True when `c`'s box is known: both corners finite. A bounding sphere and a BVH refuse a
/// child whose box is not.
bool finite_box(const rtab_component& c);

/// \brief The thesis's bounding sphere without its algorithm: the children's box, the
/// sphere around them, `BOUNDSPH { OBJECT ... }` in a scene file.
///
/// A derived class writes insert() (refuse a child whose box is unknown, then adopt() it),
/// adopt() (grow lo_ and hi_ around the child's box and set the sphere) and the ray test.
class bounding_sphere_base : public rtab_composite {
public:
    /// `BOUNDSPH`, the name in a scene file.
    std::string type_name() const override { return "BOUNDSPH"; }
    /// Reads the children: `{ OBJECT OBJECT ... }`, each through insert().
    void read(scene_reader& in) override;
    /// Removes the children and forgets the box and the sphere.
    void delete_all_children() override;
    /// The lower corner of the union of the children's boxes (NaN_point when empty).
    point min_point() const override { return lo_; }
    /// The upper corner of the union of the children's boxes (NaN_point when empty).
    point max_point() const override { return hi_; }

protected:
    bounding_sphere_base() = default;
    /// Adds `child`, whose box is known, to children_ and grows lo_, hi_ and the sphere
    /// around it (the derived class's algorithm).
    virtual void adopt(std::unique_ptr<rtab_component> child) = 0;
    /// Replaces the sphere by another that still holds every child (a fractal sphere
    /// knows a tighter one than the sphere around the box).
    void set_sphere(const point& center, double radius) {
        bound_center_ = center;
        bound_radius_ = radius;
    }

    point lo_ = NaN_point;            ///< the lower corner of the union of the children's boxes
    point hi_ = NaN_point;            ///< the upper corner of that union
    point bound_center_ = NaN_point;  ///< the centre of the sphere every ray tests first
    double bound_radius_ = 0;         ///< its radius
};

/// Throws vl::usage_error, as make_frac_sphere() does, when the centre is not finite, the
/// radius not a finite number > 0, the depth not from 0 to frac_sphere_params::max_depth
/// or the ratio not between 0 and 1.
void check_frac_sphere(const point& center, double radius, int depth, double ratio);
/// Reads `FRACSPH { center X Y Z radius R depth D ratio Q ...surface keys... }` into `p`
/// and `s` (what is not given keeps its value).
void read_frac_sphere(scene_reader& in, frac_sphere_params& p, surface& s);
/// Writes `FRACSPH { center ... ratio Q ...surface keys... }`.
void write_frac_sphere(std::ostream& out, const frac_sphere_params& p, const surface& s);

/// \brief The thesis's fractal spheres without their algorithm: a bounding sphere (the
/// class `sphere_class`, which derives from bounding_sphere_base) that makes its own
/// children, `FRACSPH { center X Y Z radius R depth D ratio Q ... }` in a scene file.
///
/// \tparam sphere_class the bounding sphere a fractal level is: its adopt() and ray
/// test serve every level.
///
/// A derived class writes build(), which makes the spheres of one level from center_,
/// radius_, depth_, ratio_, surface_ and parent_direction_, and no constructor: it is made
/// by make(), which sets the values and calls build(); read() calls build() again with
/// what it read, once the old spheres are gone.
template <class sphere_class>
class frac_sphere_base : public sphere_class {
public:
    /// `FRACSPH`, the name in a scene file.
    std::string type_name() const override { return "FRACSPH"; }
    /// Refuses: a fractal sphere makes its own children.
    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("FRACSPH makes its own spheres: insert() cannot add to it"
                          " (put the FRACSPH and the other object in a LIST)");
    }
    /// Reads the values and the surface (see read_frac_sphere()), removes the spheres and
    /// build()s new ones.
    void read(scene_reader& in) override {
        frac_sphere_params p{center_, radius_, depth_, ratio_};
        read_frac_sphere(in, p, surface_);
        center_ = p.center;
        radius_ = p.radius;
        depth_ = p.depth;
        ratio_ = p.ratio;
        this->delete_all_children();
        build();
    }
    /// Writes the `FRACSPH { ... }` it was read from, never its generated children.
    void write(std::ostream& s) const override {
        write_frac_sphere(s, {center_, radius_, depth_, ratio_}, surface_);
    }

    /// parent_direction_ of the top sphere, which has no parent.
    static constexpr int no_parent = -1;

    /// A fractal sphere of the derived type `fractal` (default-constructible) with these
    /// values (not checked: see check_frac_sphere()), built: its parent is in direction
    /// `parent_direction` (an index of `directions`, or no_parent). A constructor cannot
    /// call build(), which only the derived class defines, so every fractal sphere is made
    /// here.
    template <class fractal>
    static std::unique_ptr<fractal> make(const point& center, double radius, int depth, double ratio,
                                         const surface& s = {}, int parent_direction = no_parent) {
        auto f = std::make_unique<fractal>();
        frac_sphere_base& base = *f;
        base.center_ = center.homogenized();
        base.radius_ = radius;
        base.depth_ = depth;
        base.ratio_ = ratio;
        base.surface_ = s;
        base.parent_direction_ = parent_direction;
        base.build();
        return f;
    }

    /// A fractal sphere of these values, without its spheres (for a derived class that
    /// constructs itself; make() does not need it).
    frac_sphere_base(const point& center, double radius, int depth, double ratio, const surface& s,
                     int parent_direction)
        : center_(center.homogenized()), radius_(radius), depth_(depth), ratio_(ratio), surface_(s),
          parent_direction_(parent_direction) {}

protected:
    /// No values yet: make() sets them.
    frac_sphere_base() = default;

    /// The six axis directions; direction `k ^ 1` is the opposite of direction `k`.
    static constexpr vector directions[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

    /// Makes this level's spheres from the values below, into a fractal sphere that has
    /// none: the big sphere, the smaller fractal spheres around it and the tight bound
    /// (the derived class's algorithm).
    virtual void build() = 0;

    point center_;                       ///< the big sphere's centre, homogenized
    double radius_ = 1;                  ///< the big sphere's radius
    int depth_ = 0;                      ///< how many levels of smaller spheres there are below this one
    double ratio_ = 0.5;                 ///< a child's radius over its parent's
    surface surface_;                    ///< the surface of every sphere
    int parent_direction_ = no_parent;  ///< the index in `directions` towards the parent, or no_parent
};

/// \brief An axis-aligned box of six faces without its algorithm: its corners and surface,
/// `BOX { min X Y Z max X Y Z ... }` in a scene file.
///
/// A BOX is stage 03's *leaf* among the composites: its children are its own six faces,
/// made by the derived class, so it refuses insert() and delete_all_children() like a leaf.
/// A derived class writes make_faces(), normal(), contains() and the ray test.
class box_base : public rtab_composite {
public:
    /// `BOX`, the name in a scene file.
    std::string type_name() const override { return "BOX"; }
    /// Refuses: a box is made of its six faces.
    void insert(std::unique_ptr<rtab_component> child) override;
    /// Refuses: the faces are the box.
    void delete_all_children() override;
    point min_point() const override { return lo_; }  ///< the corner `min`
    point max_point() const override { return hi_; }  ///< the corner `max`
    /// Reads `{ min X Y Z max X Y Z ...surface keys... }`, fails when min is not below max,
    /// then set_geometry() with what it read (after the surface, so the faces get it).
    void read(scene_reader& in) override;
    /// Writes `BOX { min ... max ...surface keys... }`.
    void write(std::ostream& s) const override;

    /// Throws vl::usage_error, as make_box() does, when a corner is not finite or `lo` is
    /// not below `hi` in x, y and z.
    static void check_corners(const point& lo, const point& hi);

protected:
    box_base() = default;
    /// Stores the corners (homogenized), removes the faces and has make_faces() make new
    /// ones: the derived class's constructor calls it, and read() again.
    void set_geometry(const point& lo, const point& hi);
    /// Makes the six faces of the box from lo_ to hi_, each with surface_, into children_
    /// (the derived class's algorithm).
    virtual void make_faces() = 0;

    point lo_;         ///< the corner `min`, homogenized
    point hi_;         ///< the corner `max`, homogenized
    surface surface_;  ///< the surface of every face
};

/// \brief One object seen through a matrix, without the algorithm: the matrix, its inverse
/// and the normal matrix, the one child and its surface,
/// `TRANSFORM { STEP STEP ... OBJECT }` in a scene file.
///
/// A derived class writes the ray test, normal(), contains(), min_point() and max_point(),
/// and no constructor: make() makes it, with the functions of stage 01 it is given.
class transformed_base : public rtab_composite {
public:
    /// `TRANSFORM`, the name in a scene file.
    std::string type_name() const override { return "TRANSFORM"; }
    /// Takes the child when there is none yet; refuses a second one.
    void insert(std::unique_ptr<rtab_component> child) override;

    /// \name The child's surface (absent without a child)
    ///@{
    color clr() const override;
    double kdr() const override;
    double ksr() const override;
    double kdt() const override;
    double kst() const override;
    double n() const override;
    double ior() const override;
    double zero_t() const override;
    ///@}

    /// Reads `{ STEP STEP ... OBJECT }`: each step acts after the ones before it (a
    /// scene-file error at a step that leaves the matrix unusable), then exactly one object.
    void read(scene_reader& in) override;
    /// Writes `TRANSFORM { matrix M11 ... M44 CHILD }`, which reads back as the same object.
    void write(std::ostream& s) const override;

    /// Throws vl::usage_error, as make_transformed() does, when `object_to_world` cannot
    /// place an object (checks::unusable_matrix()).
    static void check_matrix(const matrix& object_to_world);

    /// How a matrix is inverted: stage 01's inverse() (the framework does not depend on a
    /// stage).
    using inverter = matrix (*)(const matrix& m);

    /// A `transformed` (a class derived from this one, default-constructible) that sees
    /// `child` (may be null) through `object_to_world`, as make_transformed() makes it:
    /// check_matrix(), then the matrices. `inverse` inverts every matrix, `steps` make the
    /// steps that read() reads (stage 01's functions).
    template <class transformed>
    static std::unique_ptr<transformed> make(std::unique_ptr<rtab_component> child, const matrix& object_to_world,
                                             inverter inverse, const transform_step_makers& steps) {
        check_matrix(object_to_world);
        auto made = std::make_unique<transformed>();
        static_cast<transformed_base&>(*made).set_up(std::move(child), object_to_world, steps, inverse);
        return made;
    }

protected:
    /// No child, no functions and no matrix yet: make() sets them.
    transformed_base() = default;

    /// `child` (may be null) seen through `object_to_world` (usable: see check_matrix()).
    /// `steps` make the steps that read() reads, `inverse` inverts every matrix.
    transformed_base(std::unique_ptr<rtab_component> child, const matrix& object_to_world,
                     const transform_step_makers& steps, inverter inverse);
    /// What that constructor does, for make().
    void set_up(std::unique_ptr<rtab_component> child, const matrix& object_to_world,
                const transform_step_makers& steps, inverter inverse);

    /// Sets to_world_ to `m`, to_object_ to its inverse and normal_matrix_ to the inverse's
    /// transpose.
    void set_matrix(const matrix& m);

    matrix to_world_;       ///< M, object space to world space
    matrix to_object_;      ///< M⁻¹, world space to object space
    matrix normal_matrix_;  ///< (M⁻¹)ᵀ, which takes normals to world space

private:
    transform_step_makers steps_{};
    inverter inverse_ = nullptr;
};

/// \brief A bounding volume hierarchy without its algorithm: the leaf size, the children,
/// `BVH { leaf_size K OBJECT ... }` in a scene file, and building the tree once, at the
/// first ray after a change, safely when several threads arrive at once.
///
/// A derived class writes build() (the tree over children_), the ray test, min_point()
/// and max_point(); each of these calls ensure_built() first.
class bvh_base : public rtab_composite {
public:
    /// `BVH`, the name in a scene file.
    std::string type_name() const override { return "BVH"; }
    /// Refuses a child whose box is unknown and the BVH itself, then adopt()s the child.
    void insert(std::unique_ptr<rtab_component> child) override;
    /// Removes every child; the tree is built again at the next ray.
    void delete_all_children() override;
    /// Reads `{ leaf_size K OBJECT ... }` (leaf_size optional, first if given).
    void read(scene_reader& in) override;
    /// Writes `BVH { leaf_size K` and every child, in insertion order.
    void write(std::ostream& s) const override;

    /// Throws vl::usage_error, as make_bvh() does, when `leaf_size` is not from 1 to 64.
    static void check_leaf_size(int leaf_size);

    /// An empty `bvh` (a class derived from this one, constructed from the leaf size) whose
    /// leaves hold at most `leaf_size` children, as make_bvh() makes it: check_leaf_size(),
    /// then the BVH.
    template <class bvh>
    static std::unique_ptr<bvh> make(int leaf_size) {
        check_leaf_size(leaf_size);
        return std::make_unique<bvh>(leaf_size);
    }

protected:
    /// An empty BVH whose leaves hold at most `leaf_size` children.
    explicit bvh_base(int leaf_size) : leaf_size_(leaf_size) {}

    /// Adds `child` (refusing a null pointer) and marks the tree to be built again.
    void adopt(std::unique_ptr<rtab_component> child);
    /// Calls build() when the children changed since the last build: at most one thread
    /// builds, the others wait for its tree. Call it first in every member that reads
    /// the tree.
    void ensure_built() const;
    /// Builds the tree over children_ (the derived class's algorithm). Called by
    /// ensure_built() under its lock, so it may fill `mutable` members.
    virtual void build() const = 0;

    int leaf_size_;  ///< the most children a leaf holds, 1 to 64

private:
    mutable std::mutex build_mutex_;
    mutable std::atomic<bool> built_{false};
};

}  // namespace vl::shapes
