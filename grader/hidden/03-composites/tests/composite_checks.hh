#pragma once
// What the bounding-sphere and the BVH tests check alike (grader only): what contains()
// says for a composite of two spheres, the children insert() must refuse, and the round
// trip of a composite of probes through a scene file.

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>

#include "hidden_support.hh"

namespace vl::stage03::hidden {

/// The union of the children's boxes, in long double, as they are added (none at first).
struct box_union {
    rvec lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
    void add(const rtab_component& child) {
        const rvec a = to_r(child.min_point()), b = to_r(child.max_point());
        lo = {std::min(lo.x, a.x), std::min(lo.y, a.y), std::min(lo.z, a.z)};
        hi = {std::max(hi.x, b.x), std::max(hi.y, b.y), std::max(hi.z, b.z)};
    }
};

/// Checks that the box of `c` (`of`, in words) is exactly the union `u`.
inline void check_box_is(tally& t, const rtab_component& c, const box_union& u, const std::string& of) {
    check_point(t, "min_point() of " + of, c.min_point(), u.lo, 0);
    check_point(t, "max_point() of " + of, c.max_point(), u.hi, 0);
}

/// Puts the unit spheres around (0, 0, 0) and (5, 0, 0) into `c` (an empty `type`) and
/// checks contains(): true in either sphere, false between them and beside them.
inline void check_contains_of_two_spheres(tally& t, rtab_composite& c, const std::string& type) {
    c.insert(std::make_unique<probe_sphere>(point(0, 0, 0), 1));
    c.insert(std::make_unique<probe_sphere>(point(5, 0, 0), 1));
    for (const auto& [p, want] : {std::pair{point(0.5, 0.2, 0), true}, std::pair{point(5, 0.9, 0), true},
                                  std::pair{point(2.5, 0, 0), false}, std::pair{point(0, 0, 1.5), false}}) {
        const bool got = c.contains(p);
        t.check(got == want, [&, p = p, want = want] {
            return "contains(" + show(p) + ") of a " + type + " of the unit spheres around (0, 0, 0) and (5, 0, 0) should be " +
                   (want ? "true" : "false") + "; yours is " + (got ? "true" : "false");
        });
    }
}

/// Inserts into `c` a hollow child: the box (0, 0, 0) to (1, 1, 1), which answers
/// composite_only of itself to a ray that enters it (and `names` names it so).
inline void insert_hollow_child(namer& names, rtab_composite& c) {
    auto hollow = std::make_unique<probe_hollow>(point(0, 0, 0), point(1, 1, 1));
    names.name(hollow.get(), "the hollow child (rule 2: the composite returns composite_only of itself)");
    c.insert(std::move(hollow));
}

/// Checks rule 2 (vl/intersection.hh): `r` hits nothing in `c`, so `c` returns
/// composite_only of itself. `said` says why, after the ray in words.
inline void check_composite_only_of(tally& t, const namer& names, const rtab_composite& c, const ray& r,
                                    const std::string& said) {
    const intersection got = c.intersect(r);
    t.check(got.is_composite_only() && got.object == &c,
            [&] { return show(r) + said + "; yours returned " + show(got, names); });
}

/// A child a composite must refuse, in words, and how to make it.
struct bad_child {
    std::string what;
    std::function<std::unique_ptr<rtab_component>()> make;
};

/// Checks that insert() of each of `children` into `c` (a `type`) throws vl::usage_error;
/// `also(child, message)` checks more of each refusal.
template <class Also>
void check_insert_refuses(tally& t, rtab_composite& c, const std::string& type, std::initializer_list<bad_child> children,
                          Also&& also) {
    for (const bad_child& b : children) {
        std::string message;
        const bool refused = throws_usage_error([&] { c.insert(b.make()); }, message);
        t.check(refused, [&] { return "insert() of " + b.what + " into a " + type + " should throw vl::usage_error; " + message; });
        if (refused) also(b, message);
    }
}

/// \brief The round trip of a composite through a scene file: `text` (a `type` of
/// `children` PROBEs) is read, and what was read is checked by `check(composite, set,
/// pass)` (`set` tracks the probes it holds; false: stop here) and written, and the text
/// `check_written(written)` looks at is read again (pass 1) and checked the same way.
template <class Check, class CheckWritten>
void check_read_write_read(tally& t, std::string text, const std::string& type, std::size_t children, Check&& check,
                           CheckWritten&& check_written) {
    for (int pass = 0; pass < 2; ++pass) {
        const auto object = read_one(text);
        const auto* c = dynamic_cast<const rtab_composite*>(object.get());
        VL_REQUIRE(c != nullptr && object->type_name() == type,
                   "reading \"" << text << "\" should give a " << type << "; yours gave " << object->type_name());
        probe_set set;
        for (const auto& child : c->children())
            if (const auto* p = dynamic_cast<const probe*>(child.get())) set.track(p);
        t.check(set.all.size() == children, [&] {
            return "the " + type + " read from \"" + text + "\" should hold its " + std::to_string(children) +
                   " children; it holds " + std::to_string(set.all.size());
        });
        if (!check(*c, set, pass)) break;
        const std::string written = text_of(*object);
        check_written(written);
        text = written;
    }
}

}  // namespace vl::stage03::hidden
