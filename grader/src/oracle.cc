#include "oracle.hh"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "safe_files.hh"

namespace vl::grader {

namespace fs = std::filesystem;

oracle_map load_oracle_map(const stage_info& stage) {
    const std::string fix = ": rebuild the grader with tools/setup (the build writes it)";
    const std::string text = read_regular_file(stage.oracle_map, std::size_t{64} << 20);
    if (text.empty())
        throw grader_error("the oracle map of " + stage.name + ", " + stage.oracle_map.string() + ", is missing" + fix);
    oracle_map m;
    try {
        const nlohmann::json doc = nlohmann::json::parse(text);
        m.stage = doc.at("stage").get<std::string>();
        for (const nlohmann::json& o : doc.at("objects"))
            m.objects.push_back({o.at("object").get<std::string>(), o.at("source").get<std::string>(),
                                 o.at("registration").get<bool>(),
                                 o.at("registration_takes").get<std::vector<std::string>>(),
                                 o.at("defines").get<std::set<std::string>>()});
        for (const auto& [name, p] : doc.at("pieces").items()) {
            oracle_map::piece piece{p.at("factory").get<std::string>(), {}};
            for (const nlohmann::json& w : p.at("withhold")) piece.withhold.emplace_back(w.at("object").get<std::string>());
            m.pieces[name] = piece;
        }
    } catch (const nlohmann::json::exception& e) {
        throw grader_error(stage.oracle_map.string() + " is no oracle map (" + e.what() + ")" + fix);
    }
    if (m.stage != stage.name) throw grader_error(stage.oracle_map.string() + " maps " + m.stage + ", not " + stage.name + fix);
    for (const oracle_map::object& o : m.objects)
        if (!fs::is_regular_file(o.path)) throw grader_error(o.path.string() + ", of the oracle of " + stage.name + ", is missing" + fix);
    return m;
}

std::vector<render_plan> plan_renders(const oracle_map& map, const std::vector<std::vector<std::string>>& piece_sets,
                                      std::vector<std::size_t>& index) {
    std::vector<render_plan> plans;
    index.clear();
    for (const std::vector<std::string>& set : piece_sets) {
        std::set<fs::path> left_out;
        auto leave_out = [&](const oracle_map::piece& p) { left_out.insert(p.withhold.begin(), p.withhold.end()); };
        if (set.empty())
            for (const auto& [name, p] : map.pieces) leave_out(p);
        for (const std::string& name : set)
            if (const auto p = map.pieces.find(name); p != map.pieces.end()) leave_out(p->second);
        const auto same = std::find_if(plans.begin(), plans.end(), [&](const render_plan& r) { return r.left_out == left_out; });
        index.push_back(static_cast<std::size_t>(same - plans.begin()));
        if (same != plans.end()) continue;

        render_plan r;
        r.left_out = left_out;
        std::set<std::string> kept_defines;
        for (const bool registration : {true, false})
            for (const oracle_map::object& o : map.objects) {
                if (o.registration != registration) continue;
                if (left_out.contains(o.path)) {
                    r.traps.insert(r.traps.end(), o.registration_takes.begin(), o.registration_takes.end());
                    r.forbidden.insert(o.defines.begin(), o.defines.end());
                } else {
                    r.objects.push_back(o.path);
                    kept_defines.insert(o.defines.begin(), o.defines.end());
                }
            }
        // A name a kept object defines too (a local helper of the same name) is no sign of
        // the left-out code; a trap is defined in the render, as vl_grader_withheld_reference.
        for (const std::string& s : kept_defines) r.forbidden.erase(s);
        for (const std::string& s : r.traps) r.forbidden.erase(s);
        for (const auto& [name, p] : map.pieces)
            if (!p.factory.empty() && std::find(r.traps.begin(), r.traps.end(), p.factory) != r.traps.end())
                r.withheld_pieces.insert(name);
        plans.push_back(std::move(r));
    }
    return plans;
}

}  // namespace vl::grader
