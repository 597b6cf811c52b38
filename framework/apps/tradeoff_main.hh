#pragma once
/// \file
/// \brief The tradeoff program: speed against accuracy, as charts (see `tradeoff --help`).
///
///     tradeoff SCENE [--out DIR] [--size WxH] [--spp LIST] [--samplers LIST] ...
///     tradeoff --structures [--out DIR] [--composites LIST] [--leaf TYPE] [--max-n N] ...
///
/// The first renders SCENE at 1, 2, 4, ..., 64 samples per pixel with each sample pattern
/// and measures each image's mean LDR-FLIP against a converged render (many samples per
/// pixel), against time, rays traced and intersection tests. The second fills each
/// composite type with N random spheres (N = 16, 32, ...) and measures its tests per ray
/// against N and against the time it took to build. Both write the charts
/// (vl/chart.hh: TSV, gnuplot script, SVG, PNG) and points.tsv into DIR and print one line
/// per point; `--against DIR` draws an earlier run's points (another build's, the
/// reference's) as lines under this run's marks.
#include "vl/registry.hh"

namespace vl {

/// Runs the tradeoff command line with `pieces`. Returns 0, 1 after a message on stderr
/// that says what went wrong (a file, a scene, a piece), or 2 for a wrong command line.
int tradeoff_main(int argc, char** argv, const registry& pieces);

}  // namespace vl
