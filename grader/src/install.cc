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
    auto str = [&](const char* key) { return t[key].value_or(std::string()); };
    installation in;
    in.source_dir = str("source_dir");
    in.build_dir = str("build_dir");
    in.grader_build_dir = str("grader_build_dir");
    in.cmake = str("cmake");
    in.make_program = str("make_program");
    in.prebuilt = str("prebuilt");
    in.reference_renderer = str("reference_renderer");
    in.reference_renders = str("reference_renders");
    in.generator = str("generator");
    in.cxx_compiler = str("cxx_compiler");
    in.compiler_launcher = str("compiler_launcher");
    in.build_type = str("build_type");
    in.sanitized = t["sanitized"].value_or(false);
    if (const toml::table* stages = t["stages"].as_table()) {
        for (const auto& [key, value] : *stages) {
            const toml::table& s = *value.as_table();
            stage_info info;
            info.name = std::string(key.str());
            info.number = s["number"].value_or(std::string());
            info.trusted_tests = s["trusted_tests"].value_or(std::string());
            in.stages[info.name] = info;
        }
    }
    if (in.stages.empty()) throw grader_error(file.string() + " lists no gradable stage: is reference/ there?");
    return in;
}

}  // namespace vl::grader
