#pragma once
/// \file
/// \brief The graded stage's oracle, and which of it each render program links.
///
/// A render program takes the pieces a scene grades (its `student_pieces`) from the
/// submission and every other piece of the graded stage from the oracle: the stage's
/// reference compiled a second time into namespace vl::reference_stageNN
/// (vl_grader_oracle_library in cmake/grader.cmake). It must link no reference code of the
/// pieces it grades, so a grade links one render program per distinct set of objects to
/// leave out: the oracle's objects that hold those pieces' code. Which objects those are,
/// the build derives from the compiled code (grader/src/oracle_probe.cc) and writes to
/// oracle/NN-name.json (`oracle_map` in grader.toml). The oracle's registration, which every
/// render links, still names the functions of the pieces left out: the link binds each to
/// vl_grader_withheld_reference (hidden/common/graded_pieces.cc), and the render takes
/// every piece whose function that is from the submission (`withheld_pieces`, named to it
/// in VL_GRADED_PIECES with the scene's own).
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "install.hh"

namespace vl::grader {

/// \brief oracle/NN-name.json, as the build's oracle probe wrote it.
struct oracle_map {
    struct object {
        std::filesystem::path path;
        std::string source;                           ///< the reference's .cc it is compiled from
        bool registration = false;                    ///< linked by every render
        std::vector<std::string> registration_takes;  ///< the functions the registration calls of it
        std::set<std::string> defines;                ///< its symbols of the stage's namespace
    };
    struct piece {
        std::string factory;                          ///< the function its registration calls ("": none)
        std::vector<std::filesystem::path> withhold;  ///< the objects a render that grades it leaves out
    };
    std::string stage;
    std::vector<object> objects;
    std::map<std::string, piece> pieces;              ///< by name: `camera`, `sampler:NAME`, `tracer:NAME`, `SPHERE`
};

/// Reads the stage's map (`oracle_map` in grader.toml). Throws grader_error when it is
/// missing or not the map of `stage`.
oracle_map load_oracle_map(const stage_info& stage);

/// \brief One render program of a grade: what it links of the oracle.
struct render_plan {
    std::vector<std::filesystem::path> objects;  ///< the oracle's objects it links (its registration first)
    std::set<std::filesystem::path> left_out;    ///< the oracle's objects it does not
    std::vector<std::string> traps;              ///< the left-out functions the registration calls
    std::set<std::string> withheld_pieces;       ///< the pieces whose factory is one of those
    std::set<std::string> forbidden;             ///< symbols only left-out objects define
};

/// The render programs for scenes that grade `piece_sets` (each scene's student_pieces;
/// an empty set grades every piece of the stage): one per distinct set of objects to leave
/// out, in the order first needed. `index[i]` is the plan of piece_sets[i]. Names that are
/// no piece of the stage leave nothing out.
std::vector<render_plan> plan_renders(const oracle_map& map, const std::vector<std::vector<std::string>>& piece_sets,
                                      std::vector<std::size_t>& index);

}  // namespace vl::grader
