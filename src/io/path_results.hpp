// The results files of an indentation run (`shellindent run`, docs/results.md), written from
// the column table (analysis/path_columns.hpp):
//   path.csv    one row per converged point, the table's columns (whole-shell values)
//   path.json   the same points keyed by column name, plus the run's description, status and
//               events
//   events.json the located events (type, monitor, depth, force, curvatures, step)
//   path_grid.csv (pseudo-arclength runs) the same columns at fixed depths 0, dh, 2 dh, ...,
//     interpolated on the branch between its converged points as the table says (cubic Hermite
//     with the points' depth slopes, or linearly), plus a last column `interpolated` (0: a
//     converged point, 1: interpolated); where a snap-back passes a depth several times, its
//     first passage
// Text is produced here; the caller writes it atomically (core/atomic_file.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/indentation_run.hpp"
#include "analysis/path_columns.hpp"

namespace si {

// The names of a run's method and status in path.json and the run's summary ("linear fast
// path", "active_set", "natural", "pseudo_arclength"; "completed", "reached_bound", "max_steps",
// "step_too_small", "stopped_by_callback", "start_failed", "failed").
const char* run_method_name(RunMethod method);
const char* run_status_name(RunStatus status);

// The header line of path.csv (without newline) of a run with these columns (run_columns,
// result_columns; the default: a run without damage or stability output).
std::string path_csv_header(const std::vector<PathColumn>& columns = base_columns());
std::string path_csv(const PathResult& result);
std::string path_grid_csv(const PathResult& result, double dh, double depth_max);
nlohmann::json events_json(const PathResult& result);
nlohmann::json path_json(const IndentationSetup& setup, const PathResult& result);
// path.json's `imperfection` (docs/results.md) and the run's one-line report of it.
nlohmann::json imperfection_json(const ImperfectionSeed& seed);
std::string imperfection_summary(const ImperfectionSeed& seed);

}  // namespace si
