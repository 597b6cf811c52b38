#include "build_submission.hh"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle.hh"
#include "policy.hh"
#include "safe_files.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

std::string stem_of(const std::string& file) { return fs::path(file).stem().string(); }

bool is_regular(const fs::path& p) {
    std::error_code ec;
    return fs::symlink_status(p, ec).type() == fs::file_type::regular;
}

/// What one grade's build may write in all: the preprocessed sources, the objects and
/// the linked programs together. An honest grade writes about 30 MiB. Each step is also
/// capped on its own (the file size limits below), so a build stops within a step of this.
constexpr std::uint64_t build_bytes_cap = std::uint64_t{512} << 20;
/// The largest file one compile step may write (a preprocessed source or an object).
constexpr std::uint64_t compile_file_cap = std::uint64_t{128} << 20;
/// The largest program one link may write.
constexpr std::uint64_t link_file_cap = std::uint64_t{256} << 20;

/// The regular files under `dirs` (symbolic links not followed), largest first, and
/// their total size.
struct written_files {
    std::uint64_t total = 0;
    std::vector<std::pair<std::uint64_t, std::string>> largest;  // size, name
};
written_files files_under(std::initializer_list<fs::path> dirs) {
    written_files w;
    std::error_code ec;
    for (const fs::path& d : dirs)
        for (fs::recursive_directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec))
            if (it->is_regular_file(ec)) {
                const std::uint64_t size = it->file_size(ec);
                w.total += size;
                w.largest.emplace_back(size, it->path().filename().string());
            }
    std::sort(w.largest.begin(), w.largest.end(), std::greater<>());
    if (w.largest.size() > 3) w.largest.resize(3);
    return w;
}

/// Why `step` may not be done, when the files under `dirs` are over build_bytes_cap;
/// otherwise "".
std::string over_build_cap(const std::string& step, std::initializer_list<fs::path> dirs) {
    const written_files w = files_under(dirs);
    if (w.total <= build_bytes_cap) return {};
    std::string largest;
    for (const auto& [size, name] : w.largest)
        largest += (largest.empty() ? "" : ", ") + name + " " + std::to_string(size >> 20) + " MiB";
    return step + ": not done: this build's files already take " + std::to_string(w.total >> 20) + " MiB, more than the " +
           std::to_string(build_bytes_cap >> 20) +
           " MiB one grade may write (preprocessed sources, objects and linked programs together; the largest: " +
           largest +
           "). An array with an initializer is stored whole in the object file and in every program linked from it "
           "(`int table[50000000] = {1};` is 200 MB): fill large tables at run time, or make them smaller.\n";
}

/// A prebuilt part mounted into the link sandbox under a neutral name.
struct prebuilt_part {
    fs::path host;
    std::string inside;
};

/// The program whose shared libraries the stage's programs load: the trusted test program
/// (or the reference renderer, for a stage without hidden tests).
const fs::path& library_user(const installation& in, const stage_info& stage) {
    return stage.trusted_tests.empty() ? in.reference_renderer : stage.trusted_tests;
}

/// The shared libraries the stage's programs load, as ldd lists them for library_user.
std::vector<std::string> shared_libraries(const installation& in, const stage_info& stage, const sandbox_capabilities& caps) {
    run_request ldd;
    ldd.argv = {"/usr/bin/ldd", library_user(in, stage).string()};
    ldd.cwd = in.grader_build_dir.string();
    ldd.environment = child_environment(in.grader_build_dir.string());
    ldd.sandboxed = false;
    ldd.limits.wall_seconds = 30;
    const run_result libs = run(ldd, caps);
    std::vector<std::string> shared;
    std::istringstream lines(libs.output);
    for (std::string line; std::getline(lines, line);) {
        const auto arrow = line.find("=> /");
        std::string path = arrow != std::string::npos ? line.substr(arrow + 3) : line.substr(line.find_first_not_of(" \t"));
        path = path.substr(0, path.find(' '));
        if (path.starts_with("/") && is_regular(fs::canonical(path))) shared.push_back(path);
    }
    return shared;
}

/// Every protected symbol (see check_symbols): what the parts linked with the student's
/// code and the shared libraries it runs with define.
void collect_protected(const installation& in, const std::vector<prebuilt_part>& parts,
                       const std::vector<std::string>& libraries, const sandbox_capabilities& caps,
                       std::set<std::string>& all, std::set<std::string>& strong) {
    auto nm = [&](std::vector<std::string> argv) {
        run_request rq;
        rq.argv = std::move(argv);
        rq.cwd = in.grader_build_dir.string();
        rq.environment = child_environment(in.grader_build_dir.string());
        rq.sandboxed = false;
        rq.limits.wall_seconds = 60;
        rq.limits.output_bytes = 256 << 20;
        const run_result r = run(rq, caps);
        if (!r.succeeded()) throw grader_error("nm failed on the grader's own parts: " + r.output_head(400));
        return r.output;
    };
    std::vector<std::string> argv = {"/usr/bin/nm", "-A", "-P", "-g", "--defined-only", "--no-sort"};
    for (const prebuilt_part& p : parts) argv.push_back(p.host.string());
    std::vector<std::string> shared = {"/usr/bin/nm", "-A", "-P", "-D", "--defined-only", "--no-sort"};
    shared.insert(shared.end(), libraries.begin(), libraries.end());
    // A weak copy of a shared library's C++ function in the program is normal (an inline
    // std::string member at -O0); a weak C function (open, malloc) would interpose the
    // runtime's, and a weak copy of a framework function defined out of line would take
    // its place: those are `strong`.
    const std::string statics = nm(argv), shared_libs = shared.size() > 6 ? nm(shared) : std::string();
    for (const auto& [out, from_static] : {std::pair{&statics, true}, std::pair{&shared_libs, false}})
        for (const auto& [file, s] : parse_nm(*out, *out)) {
            const std::string name = s.name.substr(0, s.name.find('@'));  // open@@GLIBC_2.2.5
            all.insert(name);
            const bool weak = s.type == 'W' || s.type == 'V' || s.type == 'w' || s.type == 'v' || s.type == 'u';
            if (from_static ? !weak : !name.starts_with("_Z")) strong.insert(name);
        }
}

/// collect_protected, measured once per build: the sets are kept in
/// build/.../grader/policy-cache/STAGE.json with the identity of every part, of the program
/// ldd looked at and of every shared library, and measured again when any of them changes.
void protected_symbols_of(const installation& in, const stage_info& stage, const std::vector<prebuilt_part>& parts,
                          const sandbox_capabilities& caps, std::set<std::string>& all, std::set<std::string>& strong) {
    const fs::path cache = in.grader_build_dir / "policy-cache" / (stage.name + ".json");
    auto identity = [&](const std::vector<std::string>& libraries) {
        std::string id = file_identity(library_user(in, stage));
        for (const prebuilt_part& p : parts) id += file_identity(p.host);
        for (const std::string& l : libraries) id += file_identity(l);
        return id;
    };
    const nlohmann::json cached = nlohmann::json::parse(read_regular_file(cache, std::size_t{64} << 20), nullptr, false);
    try {
        if (cached.is_object() && cached.at("identity") == identity(cached.at("libraries").get<std::vector<std::string>>())) {
            all = cached.at("all").get<std::set<std::string>>();
            strong = cached.at("strong").get<std::set<std::string>>();
            return;
        }
    } catch (const nlohmann::json::exception&) {
    }
    const std::vector<std::string> libraries = shared_libraries(in, stage, caps);
    collect_protected(in, parts, libraries, caps, all, strong);
    keep_cache_file(cache, nlohmann::json{{"identity", identity(libraries)}, {"libraries", libraries}, {"all", all},
                                          {"strong", strong}}.dump() + "\n");
}

/// Checks that each render program lacks the code of the oracle's objects its plan leaves
/// out: it defines none of their symbols, and each of their functions that the oracle's
/// registration calls is vl_grader_withheld_reference. One nm, in a sandbox (the programs
/// hold the student's code), for all of them. A program that fails is the grader's fault
/// (a wrong oracle map), never the student's: the grade stops.
void check_render_links(const installation& in, const fs::path& bin, const std::vector<render_plan>& plans,
                        const std::function<std::string(std::size_t)>& name, const sandbox_capabilities& caps) {
    if (plans.empty()) return;
    run_request rq;
    rq.mounts = {{bin, "/in", false}};
    rq.environment = child_environment("/scratch");
    rq.limits.wall_seconds = 60;
    rq.limits.output_bytes = 64 << 20;
    rq.argv = {"/usr/bin/nm", "-A", "-P", "--defined-only"};
    for (std::size_t k = 0; k < plans.size(); ++k) rq.argv.push_back("/in/" + name(k));
    const run_result r = run(rq, caps);
    if (!r.started || !r.succeeded() || r.output_bytes > r.output.size())
        throw grader_error("nm could not list the render programs' symbols: " + (r.started ? r.output_head(300) : r.error));
    // "FILE: NAME TYPE VALUE SIZE", mangled names without spaces. FILE is the program's path
    // inside the sandbox, or on the host in the weaker sandbox: its name tells them apart.
    std::map<std::string, std::map<std::string, std::string>> values;
    std::istringstream lines(r.output);
    for (std::string line; std::getline(lines, line);) {
        const auto colon = line.find(": ");
        if (colon == std::string::npos) continue;
        std::istringstream rest(line.substr(colon + 2));
        std::string symbol, type, value;
        if (rest >> symbol >> type >> value) values[fs::path(line.substr(0, colon)).filename().string()][symbol] = value;
    }
    for (std::size_t k = 0; k < plans.size(); ++k) {
        const std::map<std::string, std::string>& defined = values[name(k)];
        if (defined.empty()) throw grader_error("nm listed no symbol of the render program " + name(k));
        const auto trap = defined.find("vl_grader_withheld_reference");
        std::vector<std::string> wrong;
        for (const std::string& s : plans[k].forbidden)
            if (defined.contains(s)) wrong.push_back(s);
        for (const std::string& s : plans[k].traps)
            if (const auto d = defined.find(s); trap == defined.end() || d == defined.end() || d->second != trap->second)
                wrong.push_back(s + " (not bound to vl_grader_withheld_reference)");
        if (wrong.empty()) continue;
        std::string pieces, list;
        for (const std::string& p : plans[k].withheld_pieces) pieces += (pieces.empty() ? "" : ", ") + p;
        for (std::size_t i = 0; i < wrong.size() && i < 5; ++i) list += "\n  " + wrong[i];
        throw grader_error("the render program for the pieces " + pieces + " links reference code of them:" + list +
                           "\nThe oracle map of this stage (oracle/*.json in " + in.grader_build_dir.string() +
                           ") leaves out too little: fix grader/src/oracle_probe.cc, then rebuild");
    }
}

}  // namespace

/// The flags of every compile of a stage's code: the main build's code generation, plus
/// at most 50 errors and constexpr evaluation cut at 10^8 operations (GCC's default, 2^33,
/// runs for minutes), so a file that floods or stalls the compiler stops early. Without
/// debug information (-g0; GCC's code is the same with or without it, and nothing reads
/// it), which saves a sixth of each compile and much of the link; a sanitizer build keeps
/// it for its reports.
std::vector<std::string> compile_flags(const installation& in, const stage_info& stage) {
    std::vector<std::string> flags = in.cxx_flags;
    if (!in.sanitized) flags.push_back("-g0");
    flags.insert(flags.end(), {"-std=c++20", "-pipe", "-fdiagnostics-color=never", "-fmax-errors=50",
                               "-fconstexpr-ops-limit=100000000", "-Wall", "-Wextra",
                               "-ffile-prefix-map=/submission/=assignments/" + stage.name + "/"});
    return flags;
}

compile_outcome compile_sources(const installation& in, const stage_info& stage, const fs::path& sources,
                                const fs::path& contract, const std::vector<std::string>& files, const fs::path& objects,
                                const sandbox_capabilities& caps, cache_use cache, double wall_seconds) {
    const auto start = std::chrono::steady_clock::now();
    auto left = [&] {
        return wall_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const std::vector<std::string> flags = compile_flags(in, stage);
    std::vector<mount> mounts = {{sources, "/submission", false},
                                 {contract, "/vl/contract", false},
                                 {in.source_dir / "framework" / "include", "/vl/framework", false},
                                 {objects, "/out", true}};
    // The compile cache: only trusted sources write to it (seed_compile_cache); a
    // submission's compiles read it, so files identical to the reference or the stubs
    // (headers included) compile once.
    const fs::path cache_dir = in.grader_build_dir / "compile-cache";
    std::vector<std::string> cache_env;
    const bool cached = cache != cache_use::none && fs::is_directory(cache_dir);
    if (cached) {
        mounts.push_back({cache_dir, "/vl/ccache", cache == cache_use::write});
        cache_env = {"CCACHE_DIR=/vl/ccache", "CCACHE_TEMPDIR=/tmp", "CCACHE_NOHASHDIR=1", "CCACHE_MAXSIZE=2G",
                     "CCACHE_UMASK=022"};
        if (cache == cache_use::read_only) cache_env.push_back("CCACHE_READONLY=1");
    }
    compile_outcome outcome;
    std::vector<std::string> failures(files.size());
    std::size_t next = 0;
    bool over_cap = false;
    std::mutex m;
    auto worker = [&] {
        for (;;) {
            std::size_t k;
            {
                std::lock_guard lock(m);
                if (next >= files.size()) return;
                k = next++;
            }
            const std::string& file = files[k];
            const std::string stem = stem_of(file);
            if (std::string refusal = over_build_cap("compiling " + file, {objects}); !refusal.empty()) {
                std::lock_guard lock(m);
                if (!over_cap) failures[k] = std::move(refusal);  // once: the rest wait for it
                over_cap = true;
                continue;
            }
            run_request rq;
            rq.mounts = mounts;
            rq.environment = child_environment("/scratch", cache_env);
            rq.limits.memory_bytes = std::uint64_t{4} << 30;
            rq.limits.file_bytes = compile_file_cap;
            rq.limits.scratch_bytes = std::uint64_t{256} << 20;
            rq.limits.processes = 16;
            rq.argv = {in.cxx_compiler.string()};
            rq.argv.insert(rq.argv.end(), flags.begin(), flags.end());
            rq.argv.insert(rq.argv.end(), {"-I/vl/contract", "-I/submission", "-I/vl/framework", "-E",
                                           "/submission/" + file, "-o", "/out/" + stem + ".ii"});
            rq.limits.wall_seconds = std::max(1.0, std::min(30.0, left()));
            run_result r = run(rq, caps);
            if (r.succeeded()) {
                rq.argv = cached ? std::vector<std::string>{"/usr/bin/ccache", in.cxx_compiler.string()}
                                 : std::vector<std::string>{in.cxx_compiler.string()};
                rq.argv.insert(rq.argv.end(), flags.begin(), flags.end());
                rq.argv.insert(rq.argv.end(), {"-c", "/out/" + stem + ".ii", "-o", "/out/" + stem + ".o"});
                rq.limits.wall_seconds = std::max(1.0, std::min(60.0, left()));
                r = run(rq, caps);
            }
            std::lock_guard lock(m);
            if (!r.started) outcome.grader_failure = r.error;
            if (!r.succeeded()) {
                failures[k] = (r.timed_out || r.signal != 0
                                   ? file + ": the compiler " + r.describe(rq.limits.wall_seconds) +
                                         (r.signal == SIGXFSZ
                                              ? " (its output grew past " + std::to_string(compile_file_cap >> 20) + " MiB)"
                                              : "") +
                                         "\n"
                                   : std::string()) +
                              trim_compiler_errors(r.output);
            }
        }
    };
    {
        std::vector<std::jthread> workers;
        for (int t = 0; t < 2; ++t) workers.emplace_back(worker);
    }
    if (!outcome.grader_failure.empty())
        throw grader_error("the sandbox could not run the compiler: " + outcome.grader_failure);
    for (const std::string& f : failures) outcome.errors += f;
    return outcome;
}

void seed_compile_cache(const installation& in, const stage_info& stage, const fs::path& work,
                        const sandbox_capabilities& caps) {
    const fs::path cache_dir = in.grader_build_dir / "compile-cache";
    std::error_code ec;
    if (!fs::is_directory(cache_dir)) {
        try {
            make_sandbox_dir(cache_dir, caps);
        } catch (const grader_error&) {
            return;  // no cache: every file compiles, which is slower, never wrong
        }
    }
    // The stamp names what was compiled into the cache: the sources' sizes and times and
    // the compiler's flags. The same stamp: nothing to do.
    std::string stamp = in.cxx_compiler.string() + " ";
    for (const auto& flag : compile_flags(in, stage)) stamp += flag + " ";
    stamp += "\n";
    std::vector<fs::path> dirs = {in.source_dir / "reference" / stage.name, in.assignment_dir(stage)};
    for (const auto& [name, s] : in.stages) dirs.push_back(in.assignment_dir(s));
    dirs.push_back(in.source_dir / "framework" / "include" / "vl");
    for (const fs::path& d : dirs)
        for (const auto& e : fs::directory_iterator(d, ec))
            if (e.is_regular_file())
                stamp += e.path().string() + " " + std::to_string(e.file_size()) + " " +
                         std::to_string(e.last_write_time().time_since_epoch().count()) + "\n";
    const fs::path stamp_file = cache_dir.parent_path() / ("compile-cache-" + stage.number + ".stamp");
    if (read_regular_file(stamp_file, 1 << 20) == stamp) return;

    fs::create_directories(work / "contract");
    for (const auto& [name, s] : in.stages)
        if (fs::is_regular_file(in.contract_header(s)))
            fs::copy_file(in.contract_header(s), work / "contract" / in.contract_header(s).filename(),
                          fs::copy_options::overwrite_existing);
    int k = 0;
    for (const fs::path& from : {in.source_dir / "reference" / stage.name, in.assignment_dir(stage)}) {
        const fs::path sources = work / ("sources" + std::to_string(k)), objects = work / ("objects" + std::to_string(k));
        ++k;
        fs::create_directories(sources);
        std::vector<std::string> files;
        for (const auto& e : fs::directory_iterator(from))
            if (e.is_regular_file() && (e.path().extension() == ".cc" || e.path().extension() == ".hh")) {
                if (fs::exists(work / "contract" / e.path().filename())) continue;
                fs::copy_file(e.path(), sources / e.path().filename());
                if (e.path().extension() == ".cc") files.push_back(e.path().filename().string());
            }
        std::sort(files.begin(), files.end());
        make_sandbox_dir(objects, caps);
        const compile_outcome o = compile_sources(in, stage, sources, work / "contract", files, objects, caps,
                                                  cache_use::write, 600);
        if (!o.errors.empty()) return;  // the stubs or the reference do not compile: tests will say so
    }
    replace_file(stamp_file, stamp);
}

build_outcome build_submission(const prepared_submission& sub, const stage_info& stage, const installation& in,
                               const fs::path& work, const sandbox_capabilities& caps, const build_options& options) {
    build_outcome b;
    const auto start = std::chrono::steady_clock::now();
    auto left = [&] {
        return options.wall_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const fs::path objects = work / "objects", bin = work / "bin";
    std::error_code ec;
    fs::create_directories(work, ec);
    make_sandbox_dir(objects, caps);
    make_sandbox_dir(bin, caps);

    // 1. Preprocess and compile each file, two at a time.
    const compile_outcome compiled = compile_sources(in, stage, sub.sources, sub.contract, sub.files, objects, caps,
                                                     cache_use::read_only, left());
    b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!compiled.errors.empty()) {
        b.errors = with_contract_note(sub, trim_compiler_errors(compiled.errors, 40));
        return b;
    }

    // The prebuilt parts, under neutral names.
    std::vector<prebuilt_part> hidden, renderer, group;
    // With a judge, the submission's test-side program is the subject: its main and the
    // stage's calls, and no test. Without one, the hidden tests themselves.
    const bool judged = !stage.judge.empty();
    if (judged)
        for (std::size_t k = 0; k < stage.subject_objects.size(); ++k)
            hidden.push_back({stage.subject_objects[k], "/vl/prebuilt/subject" + std::to_string(k) + ".o"});
    else
        for (std::size_t k = 0; k < stage.hidden_objects.size(); ++k)
            hidden.push_back({stage.hidden_objects[k], "/vl/prebuilt/tests" + std::to_string(k) + ".o"});
    for (std::size_t k = 0; k < in.renderer_objects.size(); ++k)
        renderer.push_back({in.renderer_objects[k], "/vl/prebuilt/rt" + std::to_string(k) + ".o"});
    // The subject's group: the same, less the stages whose pieces it asks of the judge.
    std::vector<prebuilt_part> subject_group;
    for (const auto& [name, s] : in.stages) {
        if (name == stage.name) continue;
        const prebuilt_part part{s.reference_library, "/vl/prebuilt/reference_" + s.number + ".a"};
        group.push_back(part);
        if (std::find(stage.subject_without.begin(), stage.subject_without.end(), s.number) == stage.subject_without.end())
            subject_group.push_back(part);
    }
    // The graded stage's oracle, its reference under its other name, for the pieces a graded
    // scene does not take from the submission (hidden/common/graded_pieces.cc): each render
    // program links the oracle's registration and the objects of the pieces its scenes do
    // not grade (oracle.hh). The test program has none of it.
    const oracle_map oracle = load_oracle_map(stage);
    std::vector<std::size_t> render_of;
    const std::vector<render_plan> plans = plan_renders(oracle, options.scene_pieces, render_of);
    std::map<fs::path, prebuilt_part> oracle_parts;
    for (const oracle_map::object& o : oracle.objects)
        oracle_parts.emplace(o.path, prebuilt_part{o.path, "/vl/prebuilt/oracle" + std::to_string(oracle_parts.size()) + ".o"});
    for (std::size_t k = 0; k < in.framework_libraries.size(); ++k) {
        group.push_back({in.framework_libraries[k], "/vl/prebuilt/framework" + std::to_string(k) + ".a"});
        subject_group.push_back(group.back());
    }
    const prebuilt_part catch_main{in.catch_main, "/vl/prebuilt/catch_main.a"};

    // 2. The policy: the symbols of every object, and the student's lines of every source.
    if (options.policy) {
        std::vector<std::string> names;
        for (const std::string& f : sub.files) names.push_back("/in/" + stem_of(f) + ".o");
        run_request rq;
        rq.mounts = {{objects, "/in", false}};
        rq.environment = child_environment("/scratch");
        rq.limits.wall_seconds = std::max(1.0, std::min(60.0, left()));
        rq.limits.output_bytes = 64 << 20;
        rq.argv = {"/usr/bin/nm", "-A", "-P", "--no-sort"};
        rq.argv.insert(rq.argv.end(), names.begin(), names.end());
        const run_result mangled = run(rq, caps);
        rq.argv.insert(rq.argv.begin() + 1, "-C");
        const run_result demangled = run(rq, caps);
        if (!mangled.started || !demangled.started) throw grader_error("the sandbox could not run nm: " + mangled.error);
        std::vector<policy_finding> found;
        if (!mangled.succeeded() || mangled.output_bytes > mangled.output.size()) {
            found.push_back({"", 0, "nm", "has object files nm cannot list"});
        } else {
            std::set<std::string> protected_symbols, strong;
            std::vector<prebuilt_part> parts = hidden;
            parts.insert(parts.end(), renderer.begin(), renderer.end());
            for (const auto& [path, part] : oracle_parts) parts.push_back(part);
            parts.insert(parts.end(), group.begin(), group.end());
            parts.push_back(catch_main);
            protected_symbols_of(in, stage, parts, caps, protected_symbols, strong);
            // The weaker sandbox names the headers by their host paths.
            const std::vector<std::string> trusted_headers = {
                "/usr/", "/vl/framework/", "/vl/contract/", (in.source_dir / "framework" / "include").string() + "/",
                sub.contract.string() + "/"};
            std::map<std::string, std::vector<object_symbol>> per_file;
            for (auto& [file, s] : parse_nm(mangled.output, demangled.output)) per_file[file].push_back(s);
            for (const auto& e : fs::directory_iterator(sub.sources))
                for (policy_finding& p : check_raw_source(e.path().filename().string(),
                                                          read_regular_file(e.path(), std::size_t{16} << 20)))
                    found.push_back(p);
            for (const std::string& f : sub.files) {
                const auto symbols = per_file["/in/" + stem_of(f) + ".o"];
                for (policy_finding& p : check_symbols(f, symbols, protected_symbols, strong)) found.push_back(p);
                const std::string text = read_regular_file(objects / (stem_of(f) + ".ii"), std::size_t{256} << 20);
                for (policy_finding& p : check_preprocessed(text, "/submission/", trusted_headers)) found.push_back(p);
            }
        }
        if (!found.empty()) {
            b.refused = true;
            b.errors = "your code does what stage code may not do, so none of it was run:\n";
            for (std::size_t k = 0; k < found.size() && k < 20; ++k) b.errors += "  " + found[k].describe() + "\n";
            if (found.size() > 20) b.errors += "  [... " + std::to_string(found.size() - 20) + " more]\n";
            b.errors += "A stage's pieces only compute: they do not open or write files, end the process, start "
                        "processes, send signals, use the network, load code, map memory, make system calls, use "
                        "inline assembly, run code before main, touch the intersection counters or the test "
                        "framework, or replace the framework's symbols. Printing to std::cout and std::cerr is "
                        "fine. Remove what is named above and hand in again.\n";
            b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            return b;
        }
    }

    // 3. Link, seeing only objects: `first`, the student's objects, `then` (with the
    // symbols `withheld` bound to vl_grader_withheld_reference), and the group.
    auto run_link = [&](const std::string& program, const std::vector<prebuilt_part>& first,
                        const std::vector<prebuilt_part>& then, const std::vector<std::string>& withheld,
                        bool with_catch, const std::vector<prebuilt_part>& libraries, double& timeout) {
        run_request rq;
        rq.mounts = {{objects, "/in", false}, {bin, "/out", true}};
        std::vector<std::string> argv = {in.cxx_compiler.string()};
        argv.insert(argv.end(), in.link_flags.begin(), in.link_flags.end());
        // The prebuilt parts carry debug information that nothing reads in a graded program
        // (the student's own objects have none, see compile_flags): leaving it out halves the
        // link. A sanitizer build keeps it for its reports.
        if (!in.sanitized) argv.push_back("-Wl,--strip-debug");
        argv.insert(argv.end(), {"-pthread", "-o", "/out/" + program});
        auto add = [&](const prebuilt_part& p) {
            rq.mounts.push_back({p.host, p.inside, false});
            argv.push_back(p.inside);
        };
        for (const prebuilt_part& p : first) add(p);
        for (const std::string& f : sub.files) argv.push_back("/in/" + stem_of(f) + ".o");
        for (const prebuilt_part& p : then) add(p);
        for (const std::string& symbol : withheld) argv.push_back("-Wl,--defsym=" + symbol + "=vl_grader_withheld_reference");
        argv.push_back("-Wl,--start-group");
        if (with_catch) add(catch_main);
        for (const prebuilt_part& p : libraries) add(p);
        argv.push_back("-Wl,--end-group");
        argv.insert(argv.end(), in.system_libraries.begin(), in.system_libraries.end());
        rq.argv = argv;
        rq.environment = child_environment("/scratch");
        rq.limits.wall_seconds = std::max(1.0, std::min(120.0, left()));
        rq.limits.memory_bytes = std::uint64_t{4} << 30;
        rq.limits.file_bytes = link_file_cap;
        rq.limits.scratch_bytes = std::uint64_t{256} << 20;
        rq.limits.processes = 16;
        timeout = rq.limits.wall_seconds;
        return run(rq, caps);
    };
    // Why a link failed, in the student's terms.
    auto link_errors = [&](const run_result& r, double timeout) {
        if (r.timed_out) return "linking " + r.describe(timeout) + "\n";
        if (r.signal == SIGXFSZ)
            return "linking was stopped: the program grew past " + std::to_string(link_file_cap >> 20) +
                   " MiB. An array with an initializer is stored whole in every program (`int table[50000000] = "
                   "{1};` is 200 MB): fill large tables at run time, or make them smaller.\n";
        return explain_link_errors(r.output, sub.files);
    };
    auto link = [&](const std::string& program, const std::vector<prebuilt_part>& first, bool with_catch) {
        if (const std::string refusal = over_build_cap("linking", {objects, bin}); !refusal.empty()) {
            b.errors += refusal;
            return false;
        }
        double timeout = 0;
        const run_result r = run_link(program, first, {}, {}, with_catch, judged ? subject_group : group, timeout);
        if (!r.started) throw grader_error("the sandbox could not run the linker: " + r.error);
        if (!r.succeeded()) b.errors += link_errors(r, timeout);
        return r.succeeded() && is_regular(bin / program);
    };
    // The render programs (render-0, render-1, ...): the renderer, the student's objects, the
    // oracle's objects of each plan, and the functions of the pieces it leaves out bound to
    // vl_grader_withheld_reference. Two links at a time.
    auto render_name = [](std::size_t k) { return "render-" + std::to_string(k); };
    auto link_render = [&](std::size_t k, std::string& errors) {
        if (errors = over_build_cap("linking the renderer", {objects, bin}); !errors.empty()) return std::string();
        std::vector<prebuilt_part> withheld_from;
        for (const fs::path& o : plans[k].objects) withheld_from.push_back(oracle_parts.at(o));
        double timeout = 0;
        const run_result r = run_link(render_name(k), renderer, withheld_from, plans[k].traps, false, group, timeout);
        if (!r.started) return std::string("the sandbox could not run the linker: ") + r.error;
        if (!r.succeeded())
            errors = link_errors(r, timeout);
        else if (!is_regular(bin / render_name(k)))
            errors = "linking made no program\n";
        return std::string();
    };
    auto link_renders = [&] {
        std::vector<std::string> errors(plans.size()), failures(plans.size());
        std::atomic<std::size_t> next = 0;
        {
            std::vector<std::jthread> workers;
            for (int t = 0; t < 2; ++t)
                workers.emplace_back([&] {
                    for (std::size_t k; (k = next++) < plans.size();) failures[k] = link_render(k, errors[k]);
                });
        }
        for (const std::string& f : failures)
            if (!f.empty()) throw grader_error(f);
        for (const std::string& e : errors)
            if (!e.empty()) {
                b.errors += e;  // the first failed link's account: the student's code is in each
                return false;
            }
        check_render_links(in, bin, plans, render_name, caps);
        return true;
    };

    const std::string tests_name = judged ? "subject" : "hidden_tests";
    const bool tests_ok = hidden.empty() || link(tests_name, hidden, !judged);
    const bool render_ok = tests_ok && link_renders();
    b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!tests_ok || !render_ok) {
        b.errors = with_contract_note(sub, b.errors);
        return b;
    }
    b.ok = true;
    if (!hidden.empty()) b.tests = {judged ? stage.judge : fs::path(), bin / tests_name};
    for (std::size_t k = 0; k < plans.size(); ++k) b.renders.push_back({bin / render_name(k), plans[k].withheld_pieces});
    b.render_of = render_of;
    return b;
}

}  // namespace vl::grader
