// The oracle probe: which of a stage's reference files each piece's code is in, derived
// from the compiled code, so that a render program can leave out the reference of the
// pieces its scenes grade (grader/README.md, "Scenes"). The build links one probe per
// stage (cmake/grader.cmake, vl_grader_oracle_library) and runs it:
//
//   vl_grader_oracle_probe_NN --stage NN-name --reference DIR --nm NM --out FILE.json
//                             --registration OBJECT... --pieces OBJECT...
//
// The probe holds the stage's oracle registration (register.cc and the entry
// vl::graded::register_reference_pieces, compiled into vl::reference_stageNN) and, in
// place of every function the registration takes from the reference's objects (--pieces),
// a trap that throws the function's name (oracle_probe.hh). It asks the registration for
// each piece (`camera`, `sampler:NAME`, `tracer:NAME`, object types): the trap that fires
// names the piece's factory, and nm the object that defines it. A render that grades the
// piece must leave that object out, and with it every object that
//   - includes a header of the reference's folder that a left-out object's source includes
//     (bounding_sphere.hh: the fractal spheres are bounding spheres), since that header's
//     code is compiled into both;
//   - defines a symbol of the stage's namespace that a left-out object defines too (an
//     inline function or a template of the reference, a weak copy in each object), unless
//     the registration defines or calls it as well (then it is the contract's);
//   - calls a function of the stage's namespace that only left-out objects define.
// The registration objects are never left out: the functions they take from left-out
// objects are bound at the render's link to vl_grader_withheld_reference (graded_pieces.cc).
//
// FILE.json holds, per object, its source, the functions the registration takes from it
// and every symbol of the stage's namespace it defines (the grader checks that a render
// defines none of a left-out object's), and per piece its factory and the objects a render
// that grades it leaves out, each with the reason (none for a piece made without the
// reference's objects). A factory that throws anything but a trap, or a registration that
// would have to be left out, stops the build.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <cxxabi.h>

#include <nlohmann/json.hpp>

#include "oracle_probe.hh"
#include "vl/registry.hh"

namespace vl::graded {
void register_reference_pieces(registry& r);  // the oracle's entry (grader/hidden/common/reference_pieces.cc.in)
}

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct failure {
    std::string message;
};

/// `symbol` as a reader knows it (vl::reference_stage02::make_sphere(vl::point const&, double)).
std::string demangled(const std::string& symbol) {
    int status = 0;
    std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status), std::free);
    return status == 0 && d ? std::string(d.get()) : symbol;
}

struct nm_symbol {
    std::string name;  ///< mangled
    char type = '?';
    bool undefined() const { return type == 'U' || type == 'w' || type == 'v'; }
    bool global() const { return !undefined() && (std::isupper(static_cast<unsigned char>(type)) || type == 'u' || type == 'i'); }
};

/// `nm -P -A` of `files`: every symbol of each, defined or not, local or global.
std::map<std::string, std::vector<nm_symbol>> symbols_of(const std::string& nm, const std::vector<std::string>& files) {
    std::string command = nm + " -P -A";
    for (const std::string& f : files) command += " '" + f + "'";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) throw failure{"cannot run " + nm};
    std::string out;
    std::array<char, 1 << 16> buffer;
    for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) > 0;) out.append(buffer.data(), n);
    if (pclose(pipe.release()) != 0) throw failure{"nm failed on the oracle's objects: " + command};
    std::map<std::string, std::vector<nm_symbol>> per_file;
    for (const std::string& f : files) per_file[f];
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
        const auto colon = line.find(": ");
        if (colon == std::string::npos) continue;
        std::istringstream rest(line.substr(colon + 2));
        nm_symbol s;
        std::string type;
        if (!(rest >> s.name >> type) || type.size() != 1) continue;
        s.type = type[0];
        per_file[line.substr(0, colon)].push_back(s);
    }
    return per_file;
}

/// The headers of the reference's folder `dir` that `file` includes, directly or through
/// another such header: `#include "NAME"` that names a file beside the includer.
std::set<std::string> local_headers(const fs::path& file, const fs::path& dir) {
    static const std::regex include(R"(^\s*#\s*include\s*"([^"]+)\")");
    std::set<std::string> found;
    std::vector<fs::path> todo = {file};
    while (!todo.empty()) {
        const fs::path f = todo.back();
        todo.pop_back();
        std::ifstream in(f);
        if (!in) throw failure{"cannot read " + f.string()};
        for (std::string line; std::getline(in, line);) {
            std::smatch m;
            if (!std::regex_search(line, m, include)) continue;
            const fs::path header = fs::weakly_canonical(f.parent_path() / m[1].str());
            if (header.parent_path() != dir || !fs::is_regular_file(header)) continue;
            if (found.insert(header.filename().string()).second) todo.push_back(header);
        }
    }
    return found;
}

/// One of the oracle's objects, as the probe sees it.
struct object_file {
    std::string path;
    fs::path source;
    bool registration = false;
    std::vector<nm_symbol> symbols;
    std::set<std::string> headers;                 ///< the reference's headers its source includes
    std::set<std::string> stage_defined;           ///< global symbols of the stage's namespace it defines
    std::set<std::string> stage_undefined;         ///< symbols of the stage's namespace it calls
    std::vector<std::string> registration_takes;   ///< what the registration calls of it (its traps)
};

/// The factory symbol each piece's registration calls, by asking for each piece.
std::map<std::string, std::string> factories() {
    vl::registry r;
    vl::graded::register_reference_pieces(r);
    std::map<std::string, std::string> out;
    auto ask = [&](const std::string& piece, const std::function<void()>& make) {
        try {
            make();
        } catch (const vl::grader::oracle_trap& t) {
            out[piece] = t.symbol;
            return;
        } catch (const std::exception& e) {
            throw failure{"asking the oracle's registration for '" + piece + "' threw: " + e.what()};
        }
        // A piece made without any of the reference's files: nothing to leave out.
        out[piece] = "";
    };
    for (const std::string& n : r.names()) ask(n, [&] { (void)r.create(n); });
    for (const std::string& n : r.sampler_names()) ask("sampler:" + n, [&] { (void)r.make_sampler(n); });
    const vl::scene empty;
    for (const std::string& n : r.tracer_names()) ask("tracer:" + n, [&] { (void)r.make_tracer(n, empty); });
    if (r.has_camera()) ask("camera", [&] { (void)r.make_camera(vl::camera_settings{}, 4, 3); });
    return out;
}

int run(int argc, char** argv) {
    std::string stage, nm = "nm", out;
    fs::path reference;
    std::vector<std::string> registration, pieces;
    std::vector<std::string>* list = nullptr;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        const bool has_value = k + 1 < argc;
        if (a == "--stage" && has_value) stage = argv[++k], list = nullptr;
        else if (a == "--reference" && has_value) reference = fs::weakly_canonical(argv[++k]), list = nullptr;
        else if (a == "--nm" && has_value) nm = argv[++k], list = nullptr;
        else if (a == "--out" && has_value) out = argv[++k], list = nullptr;
        else if (a == "--registration") list = &registration;
        else if (a == "--pieces") list = &pieces;
        else if (list && !a.starts_with("--")) list->push_back(a);
        else throw failure{"unknown argument '" + a + "'"};
    }
    if (stage.size() < 3 || out.empty() || reference.empty() || registration.empty())
        throw failure{"usage: --stage NN-name --reference DIR --nm NM --out FILE --registration OBJECT... --pieces OBJECT..."};
    const std::string marker = "reference_stage" + stage.substr(0, 2);  // in every mangled name of the stage's namespace

    std::vector<std::string> all = registration;
    all.insert(all.end(), pieces.begin(), pieces.end());
    auto symbols = symbols_of(nm, all);
    std::vector<object_file> objects;
    for (const std::string& path : all) {
        object_file o;
        o.path = path;
        o.registration = std::find(registration.begin(), registration.end(), path) != registration.end();
        o.symbols = symbols[path];
        for (const nm_symbol& s : o.symbols) {
            if (s.name.find(marker) == std::string::npos) continue;
            if (s.undefined()) o.stage_undefined.insert(s.name);
            else if (s.global()) o.stage_defined.insert(s.name);
        }
        if (!o.registration) {
            // CMake names an object after its source: sphere.cc -> sphere.cc.o.
            const std::string name = fs::path(path).filename().string();
            o.source = reference / name.substr(0, name.size() - (name.ends_with(".o") ? 2 : 0));
            if (!fs::is_regular_file(o.source))
                throw failure{path + ": no source " + o.source.string() + " in the reference beside it"};
            o.headers = local_headers(o.source, reference);
        }
        objects.push_back(std::move(o));
    }
    auto defining = [&](const std::string& symbol) -> object_file* {
        for (object_file& o : objects)
            if (!o.registration && o.stage_defined.contains(symbol)) return &o;
        for (object_file& o : objects)
            if (!o.registration)
                for (const nm_symbol& s : o.symbols)
                    if (s.name == symbol && s.global()) return &o;
        return nullptr;
    };
    // Only functions of the stage's namespace are bound to the stand-in in a render; any
    // other that the registration took from a piece would leave the probe's link undefined.
    for (object_file& o : objects)
        if (o.registration)
            for (const nm_symbol& s : o.symbols)
                if (s.undefined() && s.name.find(marker) != std::string::npos)
                    if (object_file* from = defining(s.name)) from->registration_takes.push_back(s.name);

    // What the registration itself defines or calls is the contract's (its inline code, the
    // factories' names), not a piece's: sharing it ties no two objects together.
    std::set<std::string> contract;
    for (const object_file& o : objects)
        if (o.registration)
            for (const nm_symbol& s : o.symbols) contract.insert(s.name);
    // Why `k` must be left out with the objects `left_out` (empty: it need not).
    auto tied = [&](const object_file& k, const std::map<std::string, std::string>& left_out) -> std::string {
        for (const object_file& x : objects) {
            if (!left_out.contains(x.path)) continue;
            const std::string other = x.source.filename().string();
            for (const std::string& h : k.headers)
                if (x.headers.contains(h)) return "includes " + h + ", as " + other + " does";
            for (const std::string& s : k.stage_defined)
                if (x.stage_defined.contains(s) && !contract.contains(s)) return "defines " + demangled(s) + ", as " + other + " does";
            if (k.registration) continue;  // what it calls of a left-out object becomes a trap
            for (const std::string& s : k.stage_undefined) {
                if (!x.stage_defined.contains(s)) continue;
                bool elsewhere = false;
                for (const object_file& y : objects)
                    elsewhere |= !left_out.contains(y.path) && &y != &k && y.stage_defined.contains(s);
                if (!elsewhere) return "calls " + demangled(s) + ", which only " + other + " defines";
            }
        }
        return "";
    };
    json pieces_json = json::object();
    for (const auto& [piece, factory] : factories()) {
        json p = {{"factory", factory}, {"withhold", json::array()}};
        if (!factory.empty()) {
            const object_file* first = defining(factory);
            if (!first) throw failure{"'" + piece + "' calls " + factory + ", which no object of the oracle defines"};
            std::map<std::string, std::string> left_out = {{first->path, "defines " + demangled(factory) + ", the factory of " + piece}};
            for (bool grew = true; grew;) {
                grew = false;
                for (const object_file& k : objects) {
                    if (left_out.contains(k.path)) continue;
                    const std::string why = tied(k, left_out);
                    if (why.empty()) continue;
                    if (k.registration)
                        throw failure{k.path + " (the oracle's registration) would have to be left out with " + piece +
                                      ": it " + why};
                    left_out[k.path] = why;
                    grew = true;
                }
            }
            for (const auto& [path, why] : left_out) p["withhold"].push_back({{"object", path}, {"because", why}});
        }
        pieces_json[piece] = p;
    }

    json objects_json = json::array();
    for (const object_file& o : objects) {
        std::set<std::string> defines;  // every symbol of the stage's namespace, local ones too
        for (const nm_symbol& s : o.symbols)
            if (!s.undefined() && s.name.find(marker) != std::string::npos) defines.insert(s.name);
        objects_json.push_back({{"object", o.path},
                                {"source", o.source.string()},
                                {"registration", o.registration},
                                {"registration_takes", o.registration_takes},
                                {"defines", defines}});
    }
    const json doc = {{"stage", stage}, {"objects", objects_json}, {"pieces", pieces_json}};
    const std::string temporary = out + ".tmp";
    {
        std::ofstream f(temporary);
        f << doc.dump(1) << "\n";
        if (!f) throw failure{"cannot write " + temporary};
    }
    fs::rename(temporary, out);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const failure& f) {
        std::cerr << "oracle probe: " << f.message << "\n";
    } catch (const std::exception& e) {
        std::cerr << "oracle probe: " << e.what() << "\n";
    }
    return 1;
}
