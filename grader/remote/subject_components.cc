#include "subject_components.hh"

#include <sstream>
#include <string>

#include "calls_components.hh"

namespace vl::remote {

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
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = by_address_.find(object); it != by_address_.end()) return it->second;
    const handle h = next_handle();
    by_handle_[h] = object;
    by_address_[object] = h;
    return h;
}

void component_table::erase(handle h) {
    std::unique_ptr<rtab_component> gone;
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = by_handle_.find(h);
    if (it == by_handle_.end()) return;
    by_address_.erase(it->second);
    by_handle_.erase(it);
    if (const auto o = owned_.find(h); o != owned_.end()) {
        gone = std::move(o->second);
        owned_.erase(o);
    }
}

component_table& components() {
    static component_table* const table = new component_table();  // lives as long as the objects in it
    return *table;
}

namespace {

namespace c = calls_components;

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

}  // namespace

void add_component_handlers(std::vector<handler>& table) {
    table.resize(c::table_size);
    table[c::intersect] = [](message_reader& in, message_writer& out) {
        const auto h = in.get<handle>();
        const auto r = in.get<ray>();
        in.finish();
        const intersection i = components().at(h).intersect(r);
        out.put(i.t).put(components().name(i.object));
    };
    table[c::intersect_each] = [](message_reader& in, message_writer& out) {
        const auto objects = in.get_vector<handle>(c::max_batch);
        const auto rays = in.get_vector<ray>(c::max_batch);
        in.finish();
        if (objects.size() * rays.size() * 16 > max_message_bytes / 2)
            throw protocol_error("a batch of " + std::to_string(objects.size() * rays.size()) + " intersections is too large");
        for (const ray& r : rays)
            for (const handle h : objects) {
                const intersection i = components().at(h).intersect(r);
                out.put(i.t).put(components().name(i.object));
            }
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
