#include "judge_components.hh"

#include <algorithm>
#include <memory>
#include <mutex>
#include <span>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "grading.hh"
#include "surfaces.hh"
#include "vl/primitive.hh"

namespace vl::remote {

namespace {

namespace c = calls_components;

/// A stand-in for an object the judge did not have made (a part of another object):
/// the subject keeps it, so the judge never releases it.
class borrowed : public rtab_component {
public:
    std::string type_name() const override { return "(an object of your code's)"; }

private:
    intersection find_intersection(const ray&) const override { return intersection::none(); }
};

/// The same for a composite part: its children mirror the subject's.
class borrowed_composite : public rtab_composite {
public:
    std::string type_name() const override { return "(a composite of your code's)"; }

private:
    intersection find_intersection(const ray&) const override { return intersection::none(); }
};

/// The stand-in of a composite part of the subject's object.
class borrowed_mirror final : public remote_component<borrowed_composite>, public mirror_node {
public:
    ~borrowed_mirror() override { unlend_all(children_); }
    std::vector<std::unique_ptr<rtab_component>>& mirrored_children() override { return children_; }
};

/// What a children_tree answer names that cannot be (an object it names twice, a lent
/// handle the judge does not know): it misses every ray.
class nothing_there final : public rtab_component {
public:
    std::string type_name() const override { return "(an object your code's composite named that is not there)"; }

private:
    intersection find_intersection(const ray&) const override { return intersection::none(); }
};

struct stand_in_table {
    std::mutex mutex;
    std::unordered_map<handle, const rtab_component*> by_handle;
    std::unordered_map<handle, std::unique_ptr<remote_component<borrowed>>> borrowed_ones;
};

stand_in_table& table() {
    static stand_in_table* const t = new stand_in_table();  // stand-ins may go after main
    return *t;
}

/// \brief The judge's objects the subject has a handle of: by handle, by address, the
/// parts lent under each, and the objects made for the subject that nobody else holds.
struct lent_table {
    std::mutex mutex;
    std::unordered_map<handle, const rtab_component*> by_handle;
    std::unordered_map<const rtab_component*, handle> by_object;
    std::unordered_map<handle, std::vector<handle>> parts;  ///< handles lent under a root
    std::unordered_map<handle, handle> root;                ///< the root of each part
    std::unordered_map<handle, std::unique_ptr<rtab_component>> made;
    handle last = 0;
};

lent_table& lent() {
    static lent_table* const t = new lent_table();  // lent objects may go after main
    return *t;
}

/// The lent object `h`, or nullptr.
const rtab_component* lent_object(handle h) {
    lent_table& t = lent();
    const std::lock_guard<std::mutex> lock(t.mutex);
    const auto it = t.by_handle.find(h);
    return it == t.by_handle.end() ? nullptr : it->second;
}

/// The stand-in of `h` when the judge has one, else nullptr.
const rtab_component* known_stand_in(handle h) {
    stand_in_table& t = table();
    const std::lock_guard<std::mutex> lock(t.mutex);
    const auto it = t.by_handle.find(h);
    return it == t.by_handle.end() ? nullptr : it->second;
}

/// The stand-in of `h`, made now if the judge has none; a lent handle names the judge's
/// own object.
const rtab_component* stand_in_of(handle h) {
    if (h == 0) return nullptr;
    if ((h & lent_bit) != 0) {
        if (const rtab_component* o = lent_object(h)) return o;
        static const nothing_there* const missing = new nothing_there();
        return missing;
    }
    if (const rtab_component* known = known_stand_in(h)) return known;
    stand_in_table& t = table();
    auto made = std::make_unique<remote_component<borrowed>>();
    made->attach(h, false);
    const std::lock_guard<std::mutex> lock(t.mutex);
    const rtab_component* p = made.get();
    t.borrowed_ones[h] = std::move(made);
    return p;
}

/// Calls `op` on the object `h` with `args` and reads its one result of type T.
template <class T>
T call_for(c::op op, handle h, message_writer args, const char* what) {
    message_writer w;
    w.put(h);
    w.bytes().insert(w.bytes().end(), args.bytes().begin(), args.bytes().end());
    message_reader r = subject().call(op, w, what);
    const T value = r.get<T>();
    r.finish();
    return value;
}

/// The outcome cell rtab_component::intersect() counts for `i`.
int outcome_of(const intersection& i) {
    return i.object == nullptr ? detail::miss_outcome : i.t == 0 ? detail::composite_only_outcome : detail::hit_outcome;
}

/// grading::intersect_all for stand-ins: every object asked for a run of rays in one
/// crossing, as many rays at a time as keep an answer under a few MiB (false when one of
/// the objects is no stand-in, and the test asks them one by one).
bool intersect_batch(std::span<const rtab_component* const> objects, std::span<const ray> rays,
                     std::span<intersection> out) {
    std::vector<handle> handles;
    handles.reserve(objects.size());
    for (const rtab_component* o : objects) {
        const auto* remote = dynamic_cast<const remote_identity*>(o);
        if (remote == nullptr) return false;
        remote->bring_up_to_date();
        handles.push_back(remote->remote_id());
    }
    if (objects.empty()) return true;
    const std::size_t per_crossing = std::max<std::size_t>(1, (std::size_t{4} << 20) / (16 * objects.size()));
    for (std::size_t first = 0; first < rays.size(); first += per_crossing) {
        const std::size_t n = std::min(per_crossing, rays.size() - first);
        message_writer w;
        w.put_vector(handles).put_vector(std::vector<ray>(rays.begin() + first, rays.begin() + first + n));
        message_reader in = subject().call(c::intersect_each, w, "intersect");
        for (std::size_t k = first; k < first + n; ++k)
            for (std::size_t j = 0; j < objects.size(); ++j) {
                const auto t = in.get<double>();
                const auto hit = in.get<handle>();
                intersection& i = out[k * objects.size() + j];
                i = {t, stand_in_of(hit)};
                // Counted here as the test's own call of intersect() would have counted it.
                ++detail::thread_tallies.calls[objects[j]->is_composite()][outcome_of(i)];
            }
        add_declared(in.get<declared_counts>());
        in.finish();
    }
    return true;
}

/// The judge asks batches through its stand-ins from the start.
const bool batches_set = [] {
    grading::batch_of_intersections() = intersect_batch;
    return true;
}();

/// The lent object a call of the subject's names (its first argument).
const rtab_component& lent_argument(message_reader& in) {
    const auto h = in.get<handle>();
    const rtab_component* o = (h & lent_bit) != 0 ? lent_object(h) : nullptr;
    if (o == nullptr) throw protocol_error("no object of the judge's has the handle " + std::to_string(h));
    return *o;
}

/// The root a part of `h` is lent under: `h`'s own root, or `h`.
handle root_of(handle h) {
    lent_table& t = lent();
    const std::lock_guard<std::mutex> lock(t.mutex);
    const auto it = t.root.find(h);
    return it == t.root.end() ? h : it->second;
}

/// How the subject names `o`, an object an answer of the judge's names: a stand-in by its
/// handle, the judge's own object by a lent handle under `root`.
handle name_for_subject(const rtab_component* o, handle root) {
    if (o == nullptr) return 0;
    if (const auto* remote = dynamic_cast<const remote_identity*>(o)) return remote->remote_id();
    return lend(o, root);
}

void put_description(message_writer& out, const rtab_component& o) {
    out.put_string(o.type_name()).put(describe(o));
}

std::vector<handler> lent_handlers() {
    std::vector<handler> h(c::table_size);
    h[c::lent_intersect] = [](message_reader& in, message_writer& out) {
        const auto id = in.get<handle>();
        const auto r = in.get<ray>();
        in.finish();
        const rtab_component* o = (id & lent_bit) != 0 ? lent_object(id) : nullptr;
        if (o == nullptr) throw protocol_error("no object of the judge's has the handle " + std::to_string(id));
        const intersection i = o->intersect(r);  // counted here, in the judge's own counters
        const handle hit = i.object == o ? id : name_for_subject(i.object, root_of(id));
        out.put(i.t).put(hit);
        // A lent object hit is described as it is now: a test may change a surface between
        // calls, as in one process the student's code would see at once.
        if ((hit & lent_bit) != 0) {
            out.put(std::uint8_t{1});
            put_description(out, *i.object);
        } else {
            out.put(std::uint8_t{0});
        }
    };
    h[c::lent_normal] = [](message_reader& in, message_writer& out) {
        const rtab_component& o = lent_argument(in);
        const auto p = in.get<point>();
        in.finish();
        out.put(o.normal(p));
    };
    h[c::lent_contains] = [](message_reader& in, message_writer& out) {
        const rtab_component& o = lent_argument(in);
        const auto p = in.get<point>();
        in.finish();
        out.put(o.contains(p));
    };
    h[c::lent_write] = [](message_reader& in, message_writer& out) {
        const rtab_component& o = lent_argument(in);
        in.finish();
        std::ostringstream s;
        o.write(s);
        std::string text = s.str();
        if (text.size() > c::max_written_bytes) text.resize(c::max_written_bytes);
        out.put_string(text);
    };
    h[c::lent_describe] = [](message_reader& in, message_writer& out) {
        const rtab_component& o = lent_argument(in);
        in.finish();
        put_description(out, o);
    };
    return h;
}

}  // namespace

handle made_in_subject(op_id op, const message_writer& args, const char* what) {
    message_reader r = subject().call(op, args, what);
    const auto h = r.get<handle>();
    r.finish();
    return h;
}

void enter_stand_in(handle h, const rtab_component* stand_in) {
    const std::lock_guard<std::mutex> lock(table().mutex);
    table().by_handle[h] = stand_in;
}

void forget_stand_in(handle h) {
    const std::lock_guard<std::mutex> lock(table().mutex);
    table().by_handle.erase(h);
}

handle lend(const rtab_component* o, handle root) {
    if (o == nullptr) return 0;
    lent_table& t = lent();
    const std::lock_guard<std::mutex> lock(t.mutex);
    if (const auto it = t.by_object.find(o); it != t.by_object.end()) return it->second;
    const handle h = lent_bit | ++t.last;
    t.by_handle[h] = o;
    t.by_object[o] = h;
    if (root != 0 && root != h) {
        t.parts[root].push_back(h);
        t.root[h] = root;
    }
    return h;
}

void unlend(const rtab_component* o) noexcept {
    if (o == nullptr) return;
    lent_table& t = lent();
    const std::lock_guard<std::mutex> lock(t.mutex);
    const auto it = t.by_object.find(o);
    if (it == t.by_object.end()) return;
    const handle h = it->second;
    t.by_object.erase(it);
    t.by_handle.erase(h);
    if (const auto p = t.parts.find(h); p != t.parts.end()) {
        for (const handle part : p->second)
            if (const auto q = t.by_handle.find(part); q != t.by_handle.end()) {
                t.by_object.erase(q->second);
                t.by_handle.erase(q);
                t.root.erase(part);
            }
        t.parts.erase(p);
    }
    t.root.erase(h);
}

void unlend_all(std::vector<std::unique_ptr<rtab_component>>& objects) noexcept {
    for (const auto& o : objects) {
        if (o == nullptr) continue;
        if (dynamic_cast<const remote_identity*>(o.get()) == nullptr) unlend(o.get());
        // A stand-in's own children are taken back by its destructor.
    }
}

description describe(const rtab_component& o) {
    description d;
    d.composite = o.is_composite() ? 1 : 0;
    d.primitive = dynamic_cast<const primitive*>(&o) != nullptr ? 1 : 0;
    d.min = o.min_point();
    d.max = o.max_point();
    d.ball = o.bounding_ball();
    d.surf = grading::surface_of(o);
    return d;
}

namespace {

/// Keeps `made` under the new handle `h` (no root), with `t`'s mutex held.
void keep_locked(lent_table& t, handle h, std::unique_ptr<rtab_component> made) {
    if (t.made.size() >= c::max_made)
        throw protocol_error("your code had the judge make more than " + std::to_string(c::max_made) + " objects");
    t.by_handle[h] = made.get();
    t.by_object[made.get()] = h;
    t.made[h] = std::move(made);
}

}  // namespace

handle keep_made(std::unique_ptr<rtab_component> made) {
    lent_table& t = lent();
    const std::lock_guard<std::mutex> lock(t.mutex);
    const handle h = lent_bit | ++t.last;  // a new object: lent under no root
    keep_locked(t, h, std::move(made));
    return h;
}

void keep_made_as(handle h, std::unique_ptr<rtab_component> made) {
    if ((h & lent_bit) == 0 || (h & c::posted_bit) == 0)
        throw protocol_error("your code's process named a sphere it made with a handle it may not choose");
    lent_table& t = lent();
    const std::lock_guard<std::mutex> lock(t.mutex);
    if (t.by_handle.contains(h)) throw protocol_error("your code's process named two objects with one handle");
    keep_locked(t, h, std::move(made));
}

void released_by_subject(handle h) {
    if ((h & lent_bit) == 0) return;
    std::unique_ptr<rtab_component> gone;
    {
        lent_table& t = lent();
        const std::lock_guard<std::mutex> lock(t.mutex);
        const auto it = t.made.find(h);
        if (it == t.made.end()) return;  // held by a composite's children now, or never made
        gone = std::move(it->second);
        t.made.erase(it);
    }
    unlend(gone.get());
}

std::vector<handler>& judge_handlers() {
    static std::vector<handler>* const table = new std::vector<handler>(lent_handlers());
    return *table;
}

void add_declared(const declared_counts& d) {
    // What the student's code says it counted: never more than any test makes, so that no
    // answer can wrap a counter around.
    constexpr std::uint64_t most = detail::most_tests_per_count;
    for (int k = 0; k < 2; ++k)
        for (int o = 0; o < 3; ++o) detail::thread_tallies.calls[k][o] += std::min(d.calls[k][o], most);
    detail::thread_tallies.bounding_volume += std::min(d.bounding_volume, most);
}

void put_child(message_writer& w, const rtab_component* child) {
    if (child == nullptr) {
        w.put(child_kind::none);
    } else if (const auto* remote = dynamic_cast<const remote_identity*>(child)) {
        remote->bring_up_to_date();
        w.put(child_kind::own).put(remote->remote_id());
    } else {
        w.put(child_kind::lent).put(lend(child));
        put_description(w, *child);
    }
}

namespace {

using pool = std::unordered_map<const rtab_component*, std::unique_ptr<rtab_component>>;

/// Moves every object held under `node` (its children, and theirs in mirrors) into `p`.
void gather(mirror_node& node, pool& p) {
    for (auto& child : node.mirrored_children()) {
        if (!child) continue;
        if (auto* inner = dynamic_cast<mirror_node*>(child.get())) gather(*inner, p);
        const rtab_component* key = child.get();
        p.emplace(key, std::move(child));
    }
    node.mirrored_children().clear();
}

/// Takes `o` out of `p`; nullptr when `p` does not hold it.
std::unique_ptr<rtab_component> take(pool& p, const rtab_component* o) {
    if (o == nullptr) return nullptr;
    const auto it = p.find(o);
    if (it == p.end()) return nullptr;
    std::unique_ptr<rtab_component> out = std::move(it->second);
    p.erase(it);
    return out;
}

/// An object the judge made for the subject, taken over by a composite's children.
std::unique_ptr<rtab_component> take_made(handle h) {
    lent_table& t = lent();
    const std::lock_guard<std::mutex> lock(t.mutex);
    const auto it = t.made.find(h);
    if (it == t.made.end()) return nullptr;
    std::unique_ptr<rtab_component> out = std::move(it->second);
    t.made.erase(it);
    return out;
}

/// Fills `node`'s children from `entries` from `at` on: `count` of them, each followed by
/// its own children.
void build(mirror_node& node, const std::vector<tree_entry>& entries, const std::vector<surface>& surfaces,
           std::size_t& at, std::size_t count, pool& p) {
    auto& children = node.mirrored_children();
    for (std::size_t k = 0; k < count; ++k) {
        if (at >= entries.size()) throw protocol_error("your code's process answered children_tree with a tree cut short");
        const tree_entry& e = entries[at++];
        std::unique_ptr<rtab_component> child;
        if ((e.object & lent_bit) != 0) {
            const rtab_component* o = lent_object(e.object);
            child = take(p, o);
            if (!child && o != nullptr) child = take_made(e.object);
            if (child && e.has_surface != 0) {
                if (e.surface_index >= surfaces.size())
                    throw protocol_error("your code's process answered children_tree with a surface it did not send");
                if (auto* prim = dynamic_cast<primitive*>(child.get())) prim->set_surface(surfaces[e.surface_index]);
            }
        } else if (e.object != 0) {
            child = take(p, known_stand_in(e.object));
            if (!child) {
                if (e.composite != 0) {
                    auto m = std::make_unique<borrowed_mirror>();
                    m->attach(e.object, false);
                    child = std::move(m);
                } else {
                    auto b = std::make_unique<remote_component<borrowed>>();
                    b->attach(e.object, false);
                    child = std::move(b);
                }
            }
        }
        if (!child) child = std::make_unique<nothing_there>();
        // A lent composite's children are the judge's own: the subject names none below it.
        if (auto* inner = dynamic_cast<mirror_node*>(child.get()); inner != nullptr && e.composite != 0)
            build(*inner, entries, surfaces, at, e.children, p);
        else if (e.children != 0)
            throw protocol_error("your code's process answered children_tree with children below an object that has none");
        children.push_back(std::move(child));
    }
}

}  // namespace

void mirror_children(handle h, mirror_node& node, std::vector<std::unique_ptr<rtab_component>>& kept) {
    message_reader in = subject().call(c::children_tree, message_writer().put(h), "children");
    const auto top = in.get<std::uint32_t>();
    const auto entries = in.get_vector<tree_entry>(c::max_tree);
    const auto surfaces = in.get_vector<surface>(c::max_tree);
    in.finish();
    pool p;
    gather(node, p);
    for (auto& k : kept)
        if (k) {
            const rtab_component* key = k.get();
            p.emplace(key, std::move(k));
        }
    kept.clear();
    std::size_t at = 0;
    std::exception_ptr failed;
    try {
        build(node, entries, surfaces, at, top, p);
        if (at != entries.size()) throw protocol_error("your code's process answered children_tree with entries left over");
    } catch (...) {
        failed = std::current_exception();
    }
    // What the subject's composite no longer holds stays with the stand-in.
    for (auto& [key, object] : p) kept.push_back(std::move(object));
    if (failed) std::rethrow_exception(failed);
}

namespace component_calls {

intersection intersect(handle h, const ray& r) {
    message_writer w;
    w.put(h).put(r);
    message_reader in = subject().call(c::intersect, w, "intersect");
    const auto t = in.get<double>();
    const auto hit = in.get<handle>();
    add_declared(in.get<declared_counts>());
    in.finish();
    return {t, stand_in_of(hit)};
}
vector normal(handle h, const point& p) { return call_for<vector>(c::normal, h, message_writer().put(p), "normal"); }
bool contains(handle h, const point& p) { return call_for<bool>(c::contains, h, message_writer().put(p), "contains"); }
point min_point(handle h) { return call_for<point>(c::min_point, h, {}, "min_point"); }
point max_point(handle h) { return call_for<point>(c::max_point, h, {}, "max_point"); }
rtab_component::ball bounding_ball(handle h) {
    return call_for<rtab_component::ball>(c::bounding_ball, h, {}, "bounding_ball");
}
double zero_t(handle h) { return call_for<double>(c::zero_t, h, {}, "zero_t"); }
std::string type_name(handle h) {
    message_reader in = subject().call(c::type_name, message_writer().put(h), "type_name");
    std::string s = in.get_string();
    in.finish();
    return s;
}
std::string written(handle h) {
    message_reader in = subject().call(c::write, message_writer().put(h), "write");
    std::string s = in.get_string(c::max_written_bytes);
    in.finish();
    return s;
}
surface_values surface_of(handle h) {
    message_reader in = subject().call(c::surface_values, message_writer().put(h), "the surface's values");
    surface_values v{};
    v.clr = in.get<color>();
    v.kdr = in.get<double>();
    v.ksr = in.get<double>();
    v.kdt = in.get<double>();
    v.kst = in.get<double>();
    v.n = in.get<double>();
    v.ior = in.get<double>();
    in.finish();
    return v;
}

}  // namespace component_calls

}  // namespace vl::remote
