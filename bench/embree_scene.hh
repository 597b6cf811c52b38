#pragma once
// One scene, built twice: for the reference's BVH (through the public contract:
// stage02::make_sphere and make_triangle inserted into stage03::make_bvh) and for Embree
// 3 (RTC_GEOMETRY_TYPE_SPHERE_POINT and RTC_GEOMETRY_TYPE_TRIANGLE). Shared by
// embree_bench.cc (speed) and embree_oracle_test.cc (the reference's closest hits
// against Embree's). Every coordinate is a float, so both sides see the same numbers.

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/ray.hh"
#include "vl/rt_base_objects.hh"

namespace vl::embree_bench {

struct sphere_f { float x, y, z, r; };
struct vertex_f { float x, y, z; };
struct triangle_i { std::uint32_t a, b, c; };  ///< indices into scene_data::vertices

/// The scene's primitives: spheres, and one triangle mesh.
struct scene_data {
    std::vector<sphere_f> spheres;
    std::vector<vertex_f> vertices;
    std::vector<triangle_i> triangles;
    std::size_t size() const { return spheres.size() + triangles.size(); }
};

/// A ray in floats, its direction unit (to float precision).
struct ray_f { float ox, oy, oz, dx, dy, dz; };

/// A ray from (x, y, z) along (dx, dy, dz), made unit in double, then rounded to floats.
inline ray_f make_ray_f(double x, double y, double z, double dx, double dy, double dz) {
    const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
    return {float(x), float(y), float(z), float(dx / len), float(dy / len), float(dz / len)};
}

inline vl::ray to_vl_ray(const ray_f& r) { return {point(r.ox, r.oy, r.oz), vector(r.dx, r.dy, r.dz)}; }

/// Random numbers from a fixed seed, the same on every machine with this libstdc++ (the
/// doubles are made from the generator's bits, not by a distribution).
class rng {
public:
    explicit rng(std::uint64_t seed) : g_(seed) {}
    /// Uniform in [0, 1).
    double uniform() { return double(g_() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
    std::mt19937_64 g_;
};

/// `n` rays with origins uniform in the box [lo, hi]^3 and directions uniform on the sphere.
inline std::vector<ray_f> random_rays(std::size_t n, double lo, double hi, std::uint64_t seed) {
    rng g(seed);
    std::vector<ray_f> rays;
    rays.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = g.uniform(lo, hi), y = g.uniform(lo, hi), z = g.uniform(lo, hi);
        const double dz = g.uniform(-1, 1), phi = 2 * std::numbers::pi * g.uniform();
        const double s = std::sqrt(1 - dz * dz);
        rays.push_back(make_ray_f(x, y, z, s * std::cos(phi), s * std::sin(phi), dz));
    }
    return rays;
}

/// Which primitive: kind 0 a sphere, 1 a triangle, index into scene_data's vector.
/// `kind == none` is a miss.
struct primitive_id {
    static constexpr int none = -1;
    int kind = none;
    std::uint32_t index = 0;
    bool hit() const { return kind != none; }
    friend bool operator==(const primitive_id&, const primitive_id&) = default;
};

/// The closest hit as either side reports it.
struct hit_record {
    primitive_id id;
    double t = 0;
};

/// The reference's side: a BVH (leaf size 4, the default) of stage 02's primitives.
/// Which primitive each object is, is kept beside it in one sorted vector, so that what
/// the bookkeeping costs is known exactly (bookkeeping_bytes()).
class reference_scene {
public:
    explicit reference_scene(const scene_data& s) : bvh_(stage03::make_bvh()) {
        ids_.reserve(s.size());
        for (std::uint32_t i = 0; i < s.spheres.size(); ++i) {
            const sphere_f& p = s.spheres[i];
            add(stage02::make_sphere(point(p.x, p.y, p.z), p.r), {0, i});
        }
        const auto vertex = [&](std::uint32_t k) {
            const vertex_f& v = s.vertices.at(k);
            return point(v.x, v.y, v.z);
        };
        for (std::uint32_t i = 0; i < s.triangles.size(); ++i) {
            const triangle_i& t = s.triangles[i];
            add(stage02::make_triangle(vertex(t.a), vertex(t.b), vertex(t.c)), {1, i});
        }
        std::sort(ids_.begin(), ids_.end(), [](const entry& a, const entry& b) { return a.first < b.first; });
    }

    const rtab_component& bvh() const { return *bvh_; }

    /// What an intersection's object is, as a primitive_id (a miss, or rule 2: none).
    hit_record record(const intersection& i) const {
        if (!i.hit()) return {};
        const auto found = std::lower_bound(ids_.begin(), ids_.end(), i.object,
                                            [](const entry& e, const rtab_component* o) { return e.first < o; });
        if (found == ids_.end() || found->first != i.object)
            throw std::logic_error("the BVH returned an object it was not given");
        return {found->second, i.t};
    }

    /// The heap this class uses besides the BVH and its primitives.
    std::size_t bookkeeping_bytes() const { return ids_.capacity() * sizeof(entry); }

private:
    using entry = std::pair<const rtab_component*, primitive_id>;

    void add(std::unique_ptr<primitive> p, primitive_id id) {
        ids_.emplace_back(p.get(), id);
        bvh_->insert(std::move(p));
    }

    std::unique_ptr<rtab_composite> bvh_;
    std::vector<entry> ids_;
};

/// Embree's side: one device ("threads=1" unless told otherwise), one scene with a
/// sphere geometry (geomID 0, when there are spheres) and a triangle geometry. The scene
/// is built by commit(); the memory Embree allocates is counted by its memory monitor.
class embree_scene {
public:
    explicit embree_scene(const scene_data& s, const char* config = "threads=1") {
        device_ = rtcNewDevice(config);
        if (device_ == nullptr) throw std::runtime_error("rtcNewDevice failed: " + error_name(rtcGetDeviceError(nullptr)));
        rtcSetDeviceMemoryMonitorFunction(device_, &embree_scene::monitor, &bytes_);
        scene_ = rtcNewScene(device_);
        if (!s.spheres.empty()) {
            RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto* v = static_cast<sphere_f*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, sizeof(sphere_f), s.spheres.size()));
            std::copy(s.spheres.begin(), s.spheres.end(), v);
            sphere_geometry_ = attach(g);
        }
        if (!s.triangles.empty()) {
            RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<vertex_f*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(vertex_f), s.vertices.size()));
            std::copy(s.vertices.begin(), s.vertices.end(), v);
            auto* t = static_cast<triangle_i*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(triangle_i), s.triangles.size()));
            std::copy(s.triangles.begin(), s.triangles.end(), t);
            triangle_geometry_ = attach(g);
        }
        check("building the geometry");
    }
    ~embree_scene() {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    embree_scene(const embree_scene&) = delete;
    embree_scene& operator=(const embree_scene&) = delete;

    /// Builds Embree's BVH.
    void commit() {
        rtcCommitScene(scene_);
        check("rtcCommitScene");
    }

    /// Bytes Embree holds now (its memory monitor's running total).
    std::int64_t bytes() const { return bytes_.load(); }

    /// The RTCRayHit that asks for the closest hit of `r` beyond `tnear`.
    static RTCRayHit ray_hit(const ray_f& r, float tnear) {
        RTCRayHit h{};
        h.ray.org_x = r.ox; h.ray.org_y = r.oy; h.ray.org_z = r.oz;
        h.ray.dir_x = r.dx; h.ray.dir_y = r.dy; h.ray.dir_z = r.dz;
        h.ray.tnear = tnear;
        h.ray.tfar = std::numeric_limits<float>::infinity();
        h.ray.mask = ~0u;
        h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        h.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        return h;
    }

    /// Traces `h` (see ray_hit()) in place.
    void intersect(RTCIntersectContext& context, RTCRayHit& h) const { rtcIntersect1(scene_, &context, &h); }

    /// What a traced RTCRayHit hit.
    hit_record record(const RTCRayHit& h) const {
        if (h.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
        const int kind = h.hit.geomID == sphere_geometry_ ? 0 : 1;
        return {{kind, h.hit.primID}, h.ray.tfar};
    }

private:
    unsigned attach(RTCGeometry g) {
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        return id;
    }
    void check(const std::string& what) const {
        const RTCError e = rtcGetDeviceError(device_);
        if (e != RTC_ERROR_NONE) throw std::runtime_error("Embree: " + what + ": " + error_name(e));
    }
    static std::string error_name(RTCError e) { return "RTCError " + std::to_string(static_cast<int>(e)); }
    static bool monitor(void* user, ssize_t bytes, bool) {
        static_cast<std::atomic<std::int64_t>*>(user)->fetch_add(bytes);
        return true;
    }

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    unsigned sphere_geometry_ = RTC_INVALID_GEOMETRY_ID;
    unsigned triangle_geometry_ = RTC_INVALID_GEOMETRY_ID;
    std::atomic<std::int64_t> bytes_{0};
};

}  // namespace vl::embree_bench
