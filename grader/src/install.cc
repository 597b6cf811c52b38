#include "install.hh"

#include <unistd.h>

#include <toml++/toml.h>

namespace vl::grader {

namespace fs = std::filesystem;

const stage_info& installation::find_stage(const std::string& what) const {
    for (const auto& [name, s] : stages)
        if (what == name || what == s.number || what == name.substr(3)) return s;
    std::string known;
    for (const auto& [name, s] : stages) known += (known.empty() ? "" : ", ") + name;
    throw grader_error("no assignment '" + what + "' is gradable in this build (gradable: " + known +
                       "); name one by number (02), full name (02-sphere) or name (sphere)");
}

installation load_installation() {
    const fs::path self = fs::read_symlink("/proc/self/exe");
    const fs::path file = self.parent_path() / "grader.toml";
    if (!fs::exists(file))
        throw grader_error(file.string() + " is missing: build the grader with tools/setup (it writes that file)");
    toml::table t;
    try {
        t = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw grader_error(file.string() + ": " + std::string(e.description()) + "; rebuild with tools/setup");
    }
    auto str = [&](const toml::table& from, const char* key) { return from[key].value_or(std::string()); };
    auto list = [&](const toml::table& from, const char* key) {
        std::vector<std::string> out;
        if (const toml::array* a = from[key].as_array())
            for (const toml::node& n : *a)
                if (const auto v = n.value<std::string>(); v && !v->empty()) out.push_back(*v);
        return out;
    };
    auto paths = [&](const toml::table& from, const char* key) {
        std::vector<fs::path> out;
        for (const std::string& s : list(from, key)) out.emplace_back(s);
        return out;
    };
    installation in;
    in.source_dir = str(t, "source_dir");
    in.build_dir = str(t, "build_dir");
    in.grader_build_dir = str(t, "grader_build_dir");
    in.reference_renderer = str(t, "reference_renderer");
    in.reference_renders = str(t, "reference_renders");
    in.cxx_compiler = str(t, "cxx_compiler");
    in.cxx_flags = list(t, "cxx_flags");
    in.link_flags = list(t, "link_flags");
    in.system_libraries = list(t, "system_libraries");
    in.framework_libraries = paths(t, "framework_libraries");
    in.renderer_objects = paths(t, "renderer_objects");
    in.catch_main = str(t, "catch_main");
    in.build_type = str(t, "build_type");
    in.sanitized = t["sanitized"].value_or(false);
    if (const toml::table* stages = t["stages"].as_table()) {
        for (const auto& [key, value] : *stages) {
            const toml::table& s = *value.as_table();
            stage_info info;
            info.name = std::string(key.str());
            info.number = str(s, "number");
            info.trusted_tests = str(s, "trusted_tests");
            info.tests_on_stubs = str(s, "tests_on_stubs");
            info.reference_library = str(s, "reference_library");
            info.oracle_map = str(s, "oracle_map");
            info.hidden_objects = paths(s, "hidden_objects");
            info.judge = str(s, "judge");
            info.subject_objects = paths(s, "subject_objects");
            if (const toml::array* without = s["subject_without"].as_array())
                for (const auto& n : *without)
                    if (const auto v = n.value<std::string>()) info.subject_without.push_back(*v);
            in.stages[info.name] = info;
        }
    }
    if (in.stages.empty()) throw grader_error(file.string() + " lists no gradable stage: is reference/ there?");
    return in;
}

}  // namespace vl::grader
