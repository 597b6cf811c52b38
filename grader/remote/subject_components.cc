#include "subject_components.hh"

#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace vl::remote {

namespace {

namespace c = calls_components;

/// What this thread counted that the judge counts itself or was told already: calls on
/// lent objects (the judge counts them where it serves them), the judge's own call on an
/// object (its stand-in counted it), and what a nested answer declared. The rest of what
/// the counters grew by during a call is what the answer declares.
thread_local detail::tallies accounted;

detail::tallies difference(const detail::tallies& a, const detail::tallies& b) {
    detail::tallies d;
    for (int k = 0; k < 2; ++k)
        for (int o = 0; o < 3; ++o) d.calls[k][o] = a.calls[k][o] >= b.calls[k][o] ? a.calls[k][o] - b.calls[k][o] : 0;
    d.bounding_volume = a.bounding_volume >= b.bounding_volume ? a.bounding_volume - b.bounding_volume : 0;
    return d;
}

void add_to(detail::tallies& a, const detail::tallies& b) {
    for (int k = 0; k < 2; ++k)
        for (int o = 0; o < 3; ++o) a.calls[k][o] += b.calls[k][o];
    a.bounding_volume += b.bounding_volume;
}

int outcome_of(const intersection& i) {
    return i.object == nullptr ? detail::miss_outcome : i.t == 0 ? detail::composite_only_outcome : detail::hit_outcome;
}

/// \brief Measures what the student's code declares during one call of the judge's.
class declaration {
public:
    declaration() : counted_(detail::thread_tallies), accounted_(accounted) {}
    /// The judge's own call on an object of kind `composite` returned `i`: its stand-in
    /// counted it.
    void judge_called(bool composite, const intersection& i) { ++accounted.calls[composite ? 1 : 0][outcome_of(i)]; }
    /// What was declared since the start, now counted as told.
    declared_counts finish() {
        const detail::tallies d = difference(difference(detail::thread_tallies, counted_), difference(accounted, accounted_));
        add_to(accounted, d);
        return d;
    }

private:
    detail::tallies counted_, accounted_;
};

/// The judge's end of this thread's connection, where a lent object's calls go.
endpoint& judge_of_thread() {
    endpoint* e = judge_here();
    if (e == nullptr)
        throw protocol_error("an object the test lent your code was used on a thread your code started itself: "
                             "the grader follows the tests only on the threads the tests call on");
    return *e;
}

/// \brief What every stand-in of a lent object is: its lent handle.
class lent_identity {
public:
    virtual handle lent_id() const = 0;
    /// True for an object the student's code had the judge make (its surface is the
    /// student's code's to set).
    virtual bool made() const = 0;
    /// The judge describes the object again (a hit on it).
    virtual void describe_again(const description& d) = 0;

protected:
    ~lent_identity() = default;
};

/// The subject's stand-ins of lent objects, by handle (for a hit that names one).
struct lent_registry {
    std::mutex mutex;
    std::unordered_map<handle, const rtab_component*> by_handle;
    std::vector<std::unique_ptr<rtab_component>> met;  ///< made for a lent object first met as a hit
};

lent_registry& lent_ones() {
    static lent_registry* const r = new lent_registry();  // stand-ins may go after main
    return *r;
}

const rtab_component* object_named(handle h, const std::string* type = nullptr, const description* d = nullptr);

/// \brief The stand-in of a lent object, of base `Base`: box, ball and type as the judge
/// described them; intersect(), normal(), contains() and write() are calls to the judge.
template <class Base>
class lent_common : public Base, public lent_identity {
public:
    lent_common(handle h, std::string type, const description& d, bool made)
        : h_(h), type_(std::move(type)), d_(d), made_(made) {
        const std::lock_guard<std::mutex> lock(lent_ones().mutex);
        lent_ones().by_handle[h_] = this;
    }
    ~lent_common() override {
        {
            const std::lock_guard<std::mutex> lock(lent_ones().mutex);
            if (const auto it = lent_ones().by_handle.find(h_); it != lent_ones().by_handle.end() && it->second == this)
                lent_ones().by_handle.erase(it);
        }
        if (made_)
            if (endpoint* e = judge_here()) e->release(h_);
    }
    handle lent_id() const override { return h_; }
    bool made() const override { return made_; }
    void describe_again(const description& d) override {
        const std::lock_guard<std::mutex> lock(mutex_);
        d_ = d;
    }
    std::string type_name() const override { return type_; }
    point min_point() const override { return described().min; }
    point max_point() const override { return described().max; }
    rtab_component::ball bounding_ball() const override { return described().ball; }
    vector normal(const point& p) const override {
        message_reader in = judge_of_thread().call(c::lent_normal, message_writer().put(h_).put(p), "normal");
        const auto n = in.get<vector>();
        in.finish();
        return n;
    }
    bool contains(const point& p) const override {
        message_reader in = judge_of_thread().call(c::lent_contains, message_writer().put(h_).put(p), "contains");
        const auto inside = in.get<bool>();
        in.finish();
        return inside;
    }
    void write(std::ostream& s) const override {
        message_reader in = judge_of_thread().call(c::lent_write, message_writer().put(h_), "write");
        s << in.get_string(c::max_written_bytes);
        in.finish();
    }

protected:
    /// What the judge said of the object the last time (a test may change it between calls).
    description described() const {
        const std::lock_guard<std::mutex> lock(mutex_);
        return d_;
    }

private:
    intersection find_intersection(const ray& r) const override {
        message_reader in = judge_of_thread().call(c::lent_intersect, message_writer().put(h_).put(r), "intersect");
        const auto t = in.get<double>();
        const auto hit = in.get<handle>();
        const rtab_component* object = nullptr;
        if (in.get<std::uint8_t>() != 0) {  // a lent object, described as it is now
            std::string type = in.get_string();
            const auto d = in.get<description>();
            in.finish();
            object = hit == h_ ? this : object_named(hit, &type, &d);
            if (object == this) const_cast<lent_common*>(this)->describe_again(d);
        } else {
            in.finish();
            object = object_named(hit);
        }
        const intersection i{t, object};
        ++accounted.calls[this->is_composite() ? 1 : 0][outcome_of(i)];  // the judge counted it
        return i;
    }
    handle h_;
    std::string type_;
    mutable std::mutex mutex_;
    description d_;
    bool made_;
};

/// A lent object that is no primitive: its surface as described.
template <class Base>
class lent_with_surface final : public lent_common<Base> {
public:
    using lent_common<Base>::lent_common;
    double zero_t() const override { return this->described().surf.zero_t; }
    color clr() const override { return this->described().surf.clr; }
    double kdr() const override { return this->described().surf.kdr; }
    double ksr() const override { return this->described().surf.ksr; }
    double kdt() const override { return this->described().surf.kdt; }
    double kst() const override { return this->described().surf.kst; }
    double n() const override { return this->described().surf.n; }
    double ior() const override { return this->described().surf.ior; }
};

/// A lent primitive: a vl::primitive whose surface starts as described and is the
/// student's code's to set (children_tree tells the judge).
class lent_primitive final : public lent_common<primitive> {
public:
    lent_primitive(handle h, std::string type, const description& d, bool made)
        : lent_common<primitive>(h, std::move(type), d, made) {
        set_surface(d.surf);
    }
};

/// A stand-in of the lent object `h`. Only an object the student's code had made is a
/// vl::primitive here (its surface is the student's code's to set); a test's own object
/// answers its surface as the judge last described it.
std::unique_ptr<rtab_component> lent_stand_in(handle h, std::string type, const description& d, bool made) {
    if ((h & lent_bit) == 0) throw protocol_error("a lent object without a lent handle");
    if (made) return std::make_unique<lent_primitive>(h, std::move(type), d, made);
    if (d.composite != 0) return std::make_unique<lent_with_surface<rtab_composite>>(h, std::move(type), d, made);
    return std::make_unique<lent_with_surface<rtab_component>>(h, std::move(type), d, made);
}

/// The object a hit names: one of the subject's, or a lent one (described by the answer,
/// `type` and `d`, or asked of the judge the first time it is met).
const rtab_component* object_named(handle h, const std::string* type, const description* d) {
    if (h == 0) return nullptr;
    if ((h & lent_bit) == 0) return &components().at(h);
    {
        const std::lock_guard<std::mutex> lock(lent_ones().mutex);
        if (const auto it = lent_ones().by_handle.find(h); it != lent_ones().by_handle.end()) {
            if (d != nullptr)
                if (auto* l = const_cast<lent_identity*>(dynamic_cast<const lent_identity*>(it->second)); l && !l->made())
                    l->describe_again(*d);
            return it->second;
        }
    }
    std::string asked_type;
    description asked;
    if (d == nullptr) {
        message_reader in = judge_of_thread().call(c::lent_describe, message_writer().put(h), "the object hit");
        asked_type = in.get_string();
        asked = in.get<description>();
        in.finish();
        type = &asked_type;
        d = &asked;
    }
    std::unique_ptr<rtab_component> made = lent_stand_in(h, *type, *d, false);
    const rtab_component* p = made.get();
    const std::lock_guard<std::mutex> lock(lent_ones().mutex);
    lent_ones().met.push_back(std::move(made));
    return p;
}

/// Every object below `object` in children(), and `object`'s own children.
void parts_of(const rtab_component& object, std::vector<const rtab_component*>& out) {
    if (dynamic_cast<const lent_identity*>(&object) != nullptr) return;
    const auto* composite = dynamic_cast<const rtab_composite*>(&object);
    if (composite == nullptr) return;
    for (const auto& child : composite->children()) {
        if (!child) continue;
        out.push_back(child.get());
        if (out.size() > c::max_tree) return;
        parts_of(*child, out);
    }
}

/// A handler of a member that takes the object and the arguments `Args...` and answers
/// with one value.
template <class... Args, class F>
handler member(F f) {
    return [f](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        std::tuple<Args...> args{in.get<Args>()...};
        in.finish();
        const rtab_component& object = components().at(h);
        out.put(std::apply([&](const Args&... a) { return f(object, a...); }, args));
    };
}

/// \brief A children_tree answer: the entries in pre-order and the surfaces they name.
struct tree_answer {
    std::vector<tree_entry> entries;
    std::vector<surface> surfaces;
    std::map<const surface*, std::uint32_t> index;  ///< primitives share their surfaces
};

/// Appends `composite`'s children, and theirs, to `out` in pre-order.
void tree_of(const rtab_composite& composite, tree_answer& out) {
    for (const auto& child : composite.children()) {
        if (out.entries.size() >= c::max_tree)
            throw protocol_error("a composite with more than " + std::to_string(c::max_tree) + " objects below it");
        tree_entry e;
        e.object = components().name(child.get());
        if (!child) {
            out.entries.push_back(e);
            continue;
        }
        e.composite = child->is_composite() ? 1 : 0;
        const bool is_lent = dynamic_cast<const lent_identity*>(child.get()) != nullptr;
        if (const auto* p = dynamic_cast<const lent_primitive*>(child.get())) {
            e.has_surface = 1;
            const auto [at, added] = out.index.try_emplace(&p->surf(), static_cast<std::uint32_t>(out.surfaces.size()));
            if (added) out.surfaces.push_back(p->surf());
            e.surface_index = at->second;
        }
        const auto* inner = is_lent ? nullptr : dynamic_cast<const rtab_composite*>(child.get());
        e.children = inner != nullptr ? static_cast<std::uint32_t>(inner->children().size()) : 0;
        out.entries.push_back(e);
        if (inner != nullptr) tree_of(*inner, out);
    }
}

}  // namespace

handle component_table::add(std::unique_ptr<rtab_component> object) {
    if (!object) return 0;
    const handle h = next_handle();
    const std::lock_guard<std::mutex> lock(mutex_);
    by_handle_[h] = object.get();
    by_address_[object.get()] = h;
    owned_[h] = std::move(object);
    return h;
}

void component_table::adopt(handle into, handle from) {
    std::unique_ptr<rtab_component> gone;  // destroyed outside the lock: its destructor is the student's
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto to = owned_.find(into), made = owned_.find(from);
    if (to == owned_.end() || made == owned_.end() || into == from)
        throw protocol_error("no two objects of the judge's have the handles " + std::to_string(into) + " and " +
                             std::to_string(from));
    forget_parts_locked(*to->second);
    by_address_.erase(to->second.get());
    gone = std::move(to->second);
    to->second = std::move(made->second);
    owned_.erase(made);
    by_handle_.erase(from);
    by_handle_[into] = to->second.get();
    by_address_[to->second.get()] = into;
}

rtab_component& component_table::at(handle h) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = by_handle_.find(h);
    if (it == by_handle_.end()) throw protocol_error("no object has the handle " + std::to_string(h));
    return const_cast<rtab_component&>(*it->second);
}

handle component_table::name(const rtab_component* object) {
    if (object == nullptr) return 0;
    if (const auto* l = dynamic_cast<const lent_identity*>(object)) return l->lent_id();
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = by_address_.find(object); it != by_address_.end()) return it->second;
    const handle h = next_handle();
    by_handle_[h] = object;
    by_address_[object] = h;
    return h;
}

std::unique_ptr<rtab_component> component_table::take(handle h) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = owned_.find(h);
    if (it == owned_.end()) throw protocol_error("no object of the judge's has the handle " + std::to_string(h));
    std::unique_ptr<rtab_component> out = std::move(it->second);
    owned_.erase(it);
    return out;
}

void component_table::forget_parts_locked(const rtab_component& object) {
    std::vector<const rtab_component*> parts;
    parts_of(object, parts);
    for (const rtab_component* p : parts)
        if (const auto it = by_address_.find(p); it != by_address_.end()) {
            if (owned_.contains(it->second)) continue;
            by_handle_.erase(it->second);
            by_address_.erase(it);
        }
}

void component_table::forget_parts(handle h) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = by_handle_.find(h); it != by_handle_.end()) forget_parts_locked(*it->second);
}

void component_table::erase(handle h) {
    std::unique_ptr<rtab_component> gone;
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = by_handle_.find(h);
    if (it == by_handle_.end()) return;
    const auto o = owned_.find(h);
    if (o == owned_.end()) return;  // a part of another object, or handed over: it goes with its owner
    forget_parts_locked(*o->second);
    by_address_.erase(it->second);
    by_handle_.erase(it);
    gone = std::move(o->second);
    owned_.erase(o);
}

component_table& components() {
    static component_table* const table = new component_table();  // lives as long as the objects in it
    return *table;
}

std::unique_ptr<rtab_component> read_child(message_reader& in) {
    switch (in.get<child_kind>()) {
        case child_kind::none: return nullptr;
        case child_kind::own: return components().take(in.get<handle>());
        case child_kind::lent: {
            const auto h = in.get<handle>();
            std::string type = in.get_string();
            const auto d = in.get<description>();
            return lent_stand_in(h, std::move(type), d, false);
        }
    }
    throw protocol_error("a child of no known kind");
}

std::unique_ptr<object_list> lent_list(handle h, std::string type, const description& d) {
    if ((h & lent_bit) == 0) throw protocol_error("a lent object without a lent handle");
    return std::make_unique<lent_with_surface<object_list>>(h, std::move(type), d, false);
}

std::unique_ptr<primitive> made_by_judge(message_reader& answer) {
    const auto h = answer.get<handle>();
    std::string type = answer.get_string();
    const auto d = answer.get<description>();
    answer.finish();
    if ((h & lent_bit) == 0 || d.primitive == 0) throw protocol_error("the judge made no primitive");
    return made_by_judge(h, std::move(type), d);
}

std::unique_ptr<primitive> made_by_judge(handle h, std::string type, const description& d) {
    return std::make_unique<lent_primitive>(h, std::move(type), d, true);
}

void add_component_handlers(std::vector<handler>& table) {
    table.resize(c::table_size);
    table[c::intersect] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        const auto r = in.get<ray>();
        in.finish();
        const rtab_component& object = components().at(h);
        declaration declared;
        const intersection i = object.intersect(r);
        declared.judge_called(object.is_composite(), i);
        const declared_counts d = declared.finish();
        out.put(i.t).put(components().name(i.object)).put(d);
    };
    table[c::intersect_each] = [](message_reader& in, message_writer& out) {
        const auto objects = in.get_vector<handle>(c::max_batch);
        const auto rays = in.get_vector<ray>(c::max_batch);
        in.finish();
        if (objects.size() * rays.size() * 16 > max_message_bytes / 2)
            throw protocol_error("a batch of " + std::to_string(objects.size() * rays.size()) + " intersections is too large");
        declaration declared;
        for (const ray& r : rays)
            for (const handle h : objects) {
                const rtab_component& object = components().at(h);
                const intersection i = object.intersect(r);
                declared.judge_called(object.is_composite(), i);
                out.put(i.t).put(components().name(i.object));
            }
        out.put(declared.finish());
    };
    table[c::insert] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        std::unique_ptr<rtab_component> child = read_child(in);
        in.finish();
        rtab_component& parent = components().at(h);
        parent.insert(std::move(child));
        const auto* composite = dynamic_cast<const rtab_composite*>(&parent);
        const std::size_t count = composite != nullptr ? composite->children().size() : 0;
        out.put(static_cast<std::uint32_t>(count))
            .put(count == 0 ? handle{0} : components().name(composite->children().back().get()));
    };
    table[c::insert_each] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        const auto n = in.get<std::uint32_t>();
        if (n > c::max_batch) throw protocol_error("a batch of " + std::to_string(n) + " children");
        rtab_component& parent = components().at(h);
        for (std::uint32_t k = 0; k < n; ++k) parent.insert(read_child(in));
        in.finish();
        const auto* composite = dynamic_cast<const rtab_composite*>(&parent);
        const std::size_t count = composite != nullptr ? composite->children().size() : 0;
        out.put(static_cast<std::uint32_t>(count))
            .put(count == 0 ? handle{0} : components().name(composite->children().back().get()));
    };
    table[c::delete_all_children] = [](message_reader& in, message_writer&) {
        const auto h = in.get<handle>();
        in.finish();
        rtab_component& composite = components().at(h);
        components().forget_parts(h);
        composite.delete_all_children();
    };
    table[c::adopt] = [](message_reader& in, message_writer&) {
        const auto into = in.get<handle>(), from = in.get<handle>();
        in.finish();
        components().adopt(into, from);
    };
    table[c::children_tree] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        in.finish();
        tree_answer tree;
        const auto* composite = dynamic_cast<const rtab_composite*>(&components().at(h));
        if (composite != nullptr) tree_of(*composite, tree);
        out.put(static_cast<std::uint32_t>(composite != nullptr ? composite->children().size() : 0))
            .put_vector(tree.entries)
            .put_vector(tree.surfaces);
    };
    table[c::normal] = member<point>([](const rtab_component& o, const point& p) { return o.normal(p); });
    table[c::contains] = member<point>([](const rtab_component& o, const point& p) { return o.contains(p); });
    table[c::min_point] = member<>([](const rtab_component& o) { return o.min_point(); });
    table[c::max_point] = member<>([](const rtab_component& o) { return o.max_point(); });
    table[c::bounding_ball] = member<>([](const rtab_component& o) { return o.bounding_ball(); });
    table[c::zero_t] = member<>([](const rtab_component& o) { return o.zero_t(); });
    table[c::type_name] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        in.finish();
        out.put_string(components().at(h).type_name());
    };
    table[c::write] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        in.finish();
        std::ostringstream s;
        components().at(h).write(s);
        std::string text = s.str();
        if (text.size() > c::max_written_bytes) text.resize(c::max_written_bytes);
        out.put_string(text);
    };
    table[c::surface_values] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        in.finish();
        const rtab_component& o = components().at(h);
        out.put(o.clr()).put(o.kdr()).put(o.ksr()).put(o.kdt()).put(o.kst()).put(o.n()).put(o.ior());
    };
}

}  // namespace vl::remote
