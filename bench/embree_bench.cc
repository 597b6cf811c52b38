// embree_bench — the reference's BVH side by side with Embree 3, one thread each.
//
// For each scene (spheres-100k, spheres-1m or any spheres-N: N spheres of radius 0.005 at
// random in the unit cube; mesh: a displaced sphere of 307 200 triangles) it measures
//   - the build: the reference BVH builds on its first ray, so one intersect() is timed
//     alone; Embree's is rtcCommitScene;
//   - closest-hit tracing, in millions of rays per second: primary rays (a pinhole camera
//     outside the cube, one ray per pixel centre) and incoherent rays (origins uniform in
//     the cube, directions uniform on the sphere), through the counted
//     rtab_component::intersect() and through rtcIntersect1 (the context flag COHERENT for
//     primary rays, INCOHERENT for the others);
//   - what a ray cost the reference by the counters the grader's budgets use (vl/stats.hh):
//     box tests and child intersect() calls per ray, the BVH's own call not counted;
//   - the reference's heap per primitive (mallinfo2: from before the primitives are made to
//     after the BVH is built) and what Embree's memory monitor counts;
//   - how many closest hits agree (the same primitive, t within 1e-5 relative, or both
//     miss), and how many are of the same primitive (or both miss) whatever their t;
//   - the rays that differ, decided again in long double as the oracle test decides them
//     (exact_hits.hh): the reference right, a tie, grazing (either right), the reference
//     wrong.
//
//   embree_bench [--rays N] [--scenes spheres-100k,spheres-1m,mesh,...] [--kinds primary,incoherent]
//                [--repeat R] [--embree-config CONFIG]
//
// N rays of each kind (primary: the nearest square, default 1000 x 1000); only the kinds
// named (default both, so that a profile can take one); R passes of each trace, the
// reference's and Embree's by turns, the fastest of each side reported (default 1), and
// with R > 1 the median, lowest and highest ratio of the R pairs of passes; CONFIG is the
// string rtcNewDevice() is given (default "threads=1"; "threads=1,verbose=2" makes Embree
// print, among much else, which tree and which instruction set it chose). Build the
// release preset to run it.
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "embree_scene.hh"
#include "exact_hits.hh"

namespace {

using namespace vl::embree_bench;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Bytes in use on glibc's heap, mmapped blocks included.
std::size_t heap_in_use() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

scene_data random_spheres(std::size_t n, std::uint64_t seed) {
    rng g(seed);
    scene_data s;
    s.spheres.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = g.uniform(), y = g.uniform(), z = g.uniform();
        s.spheres.push_back({float(x), float(y), float(z), 0.005f});
    }
    return s;
}

/// A sphere of radius about 0.4 (0.32 to 0.48) around the cube's centre, its radius displaced by a sum
/// of 8 random waves. Made from a cube whose faces are n x n grids of two triangles per
/// cell, each vertex pushed out to the displaced sphere; vertices shared along the cube's
/// edges are made once, so the mesh is closed: 6 * 2 * n * n triangles.
scene_data displaced_sphere(int n, std::uint64_t seed) {
    rng g(seed);
    struct wave { double fx, fy, fz, amplitude, phase; };
    std::vector<wave> waves;
    for (int k = 0; k < 8; ++k) {
        const double dz = g.uniform(-1, 1), phi = 2 * std::numbers::pi * g.uniform(), s = std::sqrt(1 - dz * dz);
        const double frequency = g.uniform(3, 12);
        waves.push_back({frequency * s * std::cos(phi), frequency * s * std::sin(phi), frequency * dz,
                         g.uniform(0.3, 1.0) / 8, g.uniform(0, 2 * std::numbers::pi)});
    }
    scene_data s;
    std::unordered_map<std::uint64_t, std::uint32_t> made;  // grid point (i, j, k) -> vertex
    const auto vertex = [&](int i, int j, int k) {
        const std::uint64_t key = (std::uint64_t(i) * (n + 1) + j) * (n + 1) + k;
        const auto [at, is_new] = made.try_emplace(key, std::uint32_t(s.vertices.size()));
        if (is_new) {
            const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n, z = -1 + 2.0 * k / n;
            const double len = std::sqrt(x * x + y * y + z * z);
            const double ux = x / len, uy = y / len, uz = z / len;
            double bump = 0;
            for (const wave& w : waves) bump += w.amplitude * std::sin(w.fx * ux + w.fy * uy + w.fz * uz + w.phase);
            const double r = 0.4 * (1 + 0.2 * bump);
            s.vertices.push_back({float(0.5 + r * ux), float(0.5 + r * uy), float(0.5 + r * uz)});
        }
        return at->second;
    };
    // Each face: the axis it is perpendicular to (normal), the side, and a grid over the other two.
    for (int normal = 0; normal < 3; ++normal) {
        for (int side : {0, n}) {
            for (int a = 0; a < n; ++a) {
                for (int b = 0; b < n; ++b) {
                    const auto corner = [&](int da, int db) {
                        int c[3];
                        c[normal] = side;
                        c[(normal + 1) % 3] = a + da;
                        c[(normal + 2) % 3] = b + db;
                        return vertex(c[0], c[1], c[2]);
                    };
                    const std::uint32_t v00 = corner(0, 0), v10 = corner(1, 0), v01 = corner(0, 1), v11 = corner(1, 1);
                    s.triangles.push_back({v00, v10, v11});
                    s.triangles.push_back({v00, v11, v01});
                }
            }
        }
    }
    return s;
}

/// A square image of side `side` from a pinhole camera at (1.5, 1.2, -1.0) looking at the
/// cube's centre (vertical field of view 55 degrees, which holds the whole cube), one ray
/// through each pixel's centre.
std::vector<ray_f> primary_rays(int side) {
    const double ex = 1.5, ey = 1.2, ez = -1.0;
    // forward, right and up of the camera
    double fx = 0.5 - ex, fy = 0.5 - ey, fz = 0.5 - ez;
    const double fl = std::sqrt(fx * fx + fy * fy + fz * fz);
    fx /= fl, fy /= fl, fz /= fl;
    double rx = -fz, ry = 0, rz = fx;  // forward x (0, 1, 0)
    const double rl = std::sqrt(rx * rx + rz * rz);
    rx /= rl, rz /= rl;
    const double ux = ry * fz - rz * fy, uy = rz * fx - rx * fz, uz = rx * fy - ry * fx;
    const double half = std::tan(55.0 / 2 * std::numbers::pi / 180);
    std::vector<ray_f> rays;
    rays.reserve(std::size_t(side) * side);
    for (int row = 0; row < side; ++row) {
        for (int col = 0; col < side; ++col) {
            const double sx = (2 * (col + 0.5) / side - 1) * half, sy = (1 - 2 * (row + 0.5) / side) * half;
            rays.push_back(make_ray_f(ex, ey, ez, fx + sx * rx + sy * ux, fy + sx * ry + sy * uy, fz + sx * rz + sy * uz));
        }
    }
    return rays;
}

/// How long one run of `f` takes, in seconds.
double seconds_of(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return seconds_since(start);
}

bool agree(const hit_record& a, const hit_record& b) {
    if (!a.id.hit() || !b.id.hit()) return a.id.hit() == b.id.hit();
    return a.id == b.id && std::abs(a.t - b.t) <= 1e-5 * std::max(a.t, b.t);
}

/// How many spheres the scene `spheres-N` has: N a whole number, with an optional suffix k
/// (thousands) or m (millions), from 1 to 10m (spheres-100k, spheres-2500).
std::size_t sphere_count(const std::string& name) {
    const std::string prefix = "spheres-";
    const auto refuse = [&] {
        return std::runtime_error("no scene '" + name +
                                  "' (mesh, or spheres-N: N from 1 to 10m, with k for thousands or m for millions, "
                                  "such as spheres-100k)");
    };
    if (name.rfind(prefix, 0) != 0) throw refuse();
    std::string digits = name.substr(prefix.size());
    std::size_t scale = 1;
    if (!digits.empty() && (digits.back() == 'k' || digits.back() == 'm')) {
        scale = digits.back() == 'k' ? 1000 : 1000000;
        digits.pop_back();
    }
    if (digits.empty() || digits.size() > 8 || digits.find_first_not_of("0123456789") != std::string::npos) throw refuse();
    const std::size_t n = std::stoul(digits) * scale;
    if (n < 1 || n > 10000000) throw refuse();
    return n;
}

/// The seed of the scene of `n` spheres: 1 and 2 for 100 000 and 1 000 000 (the figures
/// docs/performance.md quotes), otherwise the count itself, so each size is one scene.
std::uint64_t sphere_seed(std::size_t n) { return n == 100000 ? 1 : n == 1000000 ? 2 : n; }

struct options {
    std::size_t rays = 1000000;
    std::vector<std::string> scenes{"spheres-100k", "spheres-1m", "mesh"};
    std::vector<std::string> kinds{"primary", "incoherent"};
    int repeat = 1;
    std::string embree_config = "threads=1";
};

options parse(int argc, char** argv) {
    options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
            return argv[++i];
        };
        if (a == "--rays") {
            o.rays = std::stoul(value());
        } else if (a == "--repeat") {
            o.repeat = std::max(1, std::stoi(value()));
        } else if (a == "--embree-config") {
            o.embree_config = value();
        } else if (a == "--scenes" || a == "--kinds") {
            std::vector<std::string>& names = a == "--scenes" ? o.scenes : o.kinds;
            names.clear();
            std::istringstream list(value());
            for (std::string name; std::getline(list, name, ',');) names.push_back(name);
        } else {
            throw std::runtime_error(
                "usage: embree_bench [--rays N] [--scenes spheres-100k,spheres-1m,spheres-N,mesh] [--kinds primary,incoherent] "
                "[--repeat R] [--embree-config CONFIG]");
        }
    }
    if (o.rays == 0) throw std::runtime_error("--rays must be at least 1");
    for (const std::string& scene : o.scenes) {
        if (scene != "mesh") (void)sphere_count(scene);  // refuses a bad name before any scene is built
    }
    for (const std::string& kind : o.kinds) {
        if (kind != "primary" && kind != "incoherent")
            throw std::runtime_error("no kind of rays '" + kind + "' (primary, incoherent)");
    }
    return o;
}

constexpr float zero_t = float(vl::rtab_component::default_zero_t);  // the reference's, as Embree's tnear

void run_scene(const std::string& name, const options& o) {
    scene_data s;
    if (name == "mesh") s = displaced_sphere(160, 3);
    else {
        const std::size_t n = sphere_count(name);
        s = random_spheres(n, sphere_seed(n));
    }

    const int side = std::max(1, int(std::lround(std::sqrt(double(o.rays)))));
    const std::map<std::string, std::vector<ray_f>> ray_sets{
        {"primary", primary_rays(side)}, {"incoherent", random_rays(o.rays, 0, 1, 4)}};

    // The reference: the primitives, then the BVH, built by its first ray.
    const std::size_t heap_before = heap_in_use();
    reference_scene ref(s);
    const vl::ray first = to_vl_ray(ray_sets.at("primary").front());
    const double ref_build = seconds_of([&] { (void)ref.bvh().intersect(first); });
    const std::size_t heap_after = heap_in_use();

    embree_scene emb(s, o.embree_config.c_str());
    const double emb_build = seconds_of([&] { emb.commit(); });

    for (const std::string& kind : o.kinds) {
        const std::vector<ray_f>& rays = ray_sets.at(kind);
        std::vector<vl::ray> vl_rays;
        vl_rays.reserve(rays.size());
        for (const ray_f& r : rays) vl_rays.push_back(to_vl_ray(r));
        std::vector<vl::intersection> ref_hits(rays.size());
        std::vector<RTCRayHit> asked;
        asked.reserve(rays.size());
        for (const ray_f& r : rays) asked.push_back(embree_scene::ray_hit(r, zero_t));
        std::vector<RTCRayHit> emb_hits;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = kind == "primary" ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                       : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
        // The passes alternate, one of the reference's then one of Embree's, so that a
        // stretch of the machine's other load slows both alike; each side's fastest pass
        // is reported, and each pair's ratio too, to show how far the load moved it.
        double ref_s = INFINITY, emb_s = INFINITY;
        std::vector<double> pass_ratios;
        vl::intersection_counts cost{};
        for (int k = 0; k < o.repeat; ++k) {
            const vl::intersection_counts counts_before = vl::counts();
            const double ref_pass = seconds_of([&] {
                for (std::size_t i = 0; i < rays.size(); ++i) ref_hits[i] = ref.bvh().intersect(vl_rays[i]);
            });
            cost += vl::counts() - counts_before;
            emb_hits = asked;
            const double emb_pass = seconds_of([&] {
                for (RTCRayHit& h : emb_hits) emb.intersect(context, h);
            });
            ref_s = std::min(ref_s, ref_pass);
            emb_s = std::min(emb_s, emb_pass);
            pass_ratios.push_back(emb_pass / ref_pass);
        }
        std::sort(pass_ratios.begin(), pass_ratios.end());

        std::size_t agreeing = 0, same_primitive = 0, ref_hit_count = 0, emb_hit_count = 0;
        std::size_t decided[5] = {};  // the rays that differ, by what long double says (exact_hits.hh)
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const hit_record a = ref.record(ref_hits[i]), b = emb.record(emb_hits[i]);
            const bool same = agree(a, b);
            agreeing += same;
            same_primitive += a.id == b.id;
            ref_hit_count += a.id.hit();
            emb_hit_count += b.id.hit();
            if (!same) ++decided[int(decide(exact(rays[i]), s, a, b))];
        }
        const double ref_mrays = rays.size() / ref_s / 1e6, emb_mrays = rays.size() / emb_s / 1e6;
        std::printf("scene=%s rays=%s reference_mrays=%.3g embree_mrays=%.3g ratio=%.3g\n", name.c_str(), kind.c_str(),
                    ref_mrays, emb_mrays, ref_mrays / emb_mrays);
        if (pass_ratios.size() > 1) {
            const std::size_t n = pass_ratios.size();
            const double median = n % 2 ? pass_ratios[n / 2] : (pass_ratios[n / 2 - 1] + pass_ratios[n / 2]) / 2;
            std::printf("scene=%s rays=%s pass_ratios: median=%.3g lowest=%.3g highest=%.3g\n", name.c_str(),
                        kind.c_str(), median, pass_ratios.front(), pass_ratios.back());
        }
        const double passes = double(o.repeat) * double(rays.size());
        std::printf("scene=%s rays=%s reference_per_ray: box_tests=%.3g child_tests=%.3g\n", name.c_str(), kind.c_str(),
                    double(cost.bounding_volume_tests) / passes,
                    double(cost.primitive_tests + cost.composite_tests) / passes - 1);
        std::printf("scene=%s rays=%s count=%zu agree=%zu same_primitive=%zu reference_hits=%zu embree_hits=%zu\n",
                    name.c_str(), kind.c_str(), rays.size(), agreeing, same_primitive, ref_hit_count, emb_hit_count);
        std::printf("scene=%s rays=%s differ=%zu reference_right=%zu tie=%zu grazing=%zu reference_wrong=%zu\n",
                    name.c_str(), kind.c_str(), rays.size() - agreeing, decided[int(verdict::reference_right)],
                    decided[int(verdict::tie)], decided[int(verdict::grazing)], decided[int(verdict::reference_wrong)]);
        std::fflush(stdout);
    }
    std::printf("scene=%s build reference_s=%.3g embree_s=%.3g ratio=%.3g\n", name.c_str(), ref_build, emb_build,
                ref_build / emb_build);
    std::printf("scene=%s reference_bytes_per_primitive=%.1f\n", name.c_str(),
                double(heap_after - heap_before - ref.bookkeeping_bytes()) / double(s.size()));
    std::printf("scene=%s embree_bytes_per_primitive=%.1f\n", name.c_str(), double(emb.bytes()) / double(s.size()));
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const options o = parse(argc, argv);
        std::printf("# embree_bench: the reference on one thread, %zu rays of each kind, fastest of %d pass(es); Embree %s, device \"%s\"\n",
                    o.rays, o.repeat, RTC_VERSION_STRING, o.embree_config.c_str());
        for (const std::string& name : o.scenes) run_scene(name, o);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "embree_bench: %s\n", e.what());
        return 1;
    }
}
