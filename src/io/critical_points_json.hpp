// The named critical points of a run in its results (docs/results.md, "critical_points"):
// path.json's `critical_points` object, the run's summary lines on stdout, and their reading
// back by the sweep table. "None" is written as such: an empty list, an onset with status
// "none" and the largest deviation reached; bifurcations null when path.stability was off.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/critical_point.hpp"

namespace si {

// "nonlinearity_onset", "stiffness_min", "stiffness_max", "depth_turn", "force_max",
// "force_min", "bifurcation"; "found", "none", "linear_kinematics", "local_law",
// "too_few_points".
const char* critical_kind_name(CriticalKind kind);
const char* onset_status_name(OnsetStatus status);

nlohmann::json critical_points_json(const CriticalPoints& points);

// One line per kind of point, for the run's summary ("critical point: ...").
std::vector<std::string> critical_points_summary(const CriticalPoints& points);

// The sweep table's columns of the critical points (the onset, the first stiffness minimum, the
// first limit point, the first bifurcation: depth and force each), and their values read from a
// path.json (NaN where there is none).
const std::vector<std::string>& critical_point_columns();
void summarize_critical_points(const nlohmann::json& path, nlohmann::json& row);

}  // namespace si
