#include "judge_components.hh"

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "grading.hh"

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

struct stand_in_table {
    std::mutex mutex;
    std::map<handle, const rtab_component*> by_handle;
    std::map<handle, std::unique_ptr<remote_component<borrowed>>> borrowed_ones;
};

stand_in_table& table() {
    static stand_in_table* const t = new stand_in_table();  // stand-ins may go after main
    return *t;
}

/// The stand-in of `h`, made now if the judge has none.
const rtab_component* stand_in_of(handle h) {
    if (h == 0) return nullptr;
    stand_in_table& t = table();
    {
        const std::lock_guard<std::mutex> lock(t.mutex);
        if (const auto it = t.by_handle.find(h); it != t.by_handle.end()) return it->second;
    }
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
                const int outcome = i.object == nullptr ? detail::miss_outcome
                                    : i.t == 0          ? detail::composite_only_outcome
                                                        : detail::hit_outcome;
                ++detail::thread_tallies.calls[objects[j]->is_composite()][outcome];
            }
        in.finish();
    }
    return true;
}

/// The judge asks batches through its stand-ins from the start.
const bool batches_set = [] {
    grading::batch_of_intersections() = intersect_batch;
    return true;
}();

}  // namespace

void enter_stand_in(handle h, const rtab_component* stand_in) {
    const std::lock_guard<std::mutex> lock(table().mutex);
    table().by_handle[h] = stand_in;
}

void forget_stand_in(handle h) {
    const std::lock_guard<std::mutex> lock(table().mutex);
    table().by_handle.erase(h);
}

namespace component_calls {

intersection intersect(handle h, const ray& r) {
    message_writer w;
    w.put(h).put(r);
    message_reader in = subject().call(c::intersect, w, "intersect");
    const auto t = in.get<double>();
    const auto hit = in.get<handle>();
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
