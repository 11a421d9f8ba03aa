// The results files of an indentation run (`shellindent run`, docs/results.md):
//   path.csv    one row per converged point, columns (whole-shell values):
//     depth_mm, force_N, reaction_N, apex_w_mm, contact_radius_mm, contact_area_mm2,
//     contact_nodes, k11_per_mm, k12_per_mm, k22_per_mm, energy_Nmm, work_Nmm, min_gap_mm,
//     min_multiplier_N, max_complementarity_Nmm, iterations, step, local_indent_mm,
//     local_energy_Nmm
//   path.json   the same points plus the run's description, status and events
//   events.json the located events (type, monitor, depth, force, curvatures, step)
//   path_grid.csv (pseudo-arclength runs) the same columns at fixed depths 0, dh, 2 dh, ...,
//     interpolated on the branch between its converged points (force, apex deflection and
//     curvatures by cubic Hermite with the points' depth slopes, the rest linearly), plus a last
//     column
//     `interpolated` (0: a converged point, 1: interpolated); where a snap-back passes a depth
//     several times, its first passage
// Text is produced here; the caller writes it atomically (core/atomic_file.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/indentation_run.hpp"

namespace si {

// The names of a run's method and status in path.json and the run's summary ("linear fast
// path", "active_set", "natural", "pseudo_arclength"; "completed", "reached_bound", "max_steps",
// "step_too_small", "stopped_by_callback", "start_failed", "failed").
const char* run_method_name(RunMethod method);
const char* run_status_name(RunStatus status);

// The header line of path.csv (without newline).
std::string path_csv_header();
std::string path_csv(const PathResult& result);
std::string path_grid_csv(const PathResult& result, double dh, double depth_max);
nlohmann::json events_json(const PathResult& result);
nlohmann::json path_json(const IndentationSetup& setup, const PathResult& result);

}  // namespace si
