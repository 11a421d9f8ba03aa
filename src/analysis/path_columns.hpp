// The result columns of an indentation path, declared once: name, unit, meaning, how the value
// is computed from a point, whether the continuation monitors it and how path_grid.csv
// interpolates it. Everything that reads or writes a column goes through this table: path.csv,
// path.json and path_grid.csv (io/path_results.hpp), the checkpoint's points
// (indentation_run.cpp), the continuation's monitors (IndentationOptions::monitors), the events,
// the sweep's merged table (app/sweep_command.cpp), docs/results.md and studies/result_columns.py
// (both generated from it by scripts/update_schema.sh; tests/io/test_column_tables.cpp fails
// if they differ from it).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/indentation_run.hpp"

namespace si {

// In path.csv's order.
enum class PathColumn {
  kDepth,
  kForce,
  kReaction,
  kApexDeflection,
  kContactRadius,
  kContactArea,
  kContactNodes,
  kK11,
  kK12,
  kK22,
  kEnergy,
  kWork,
  kMinGap,
  kMinMultiplier,
  kMaxComplementarity,
  kIterations,
  kStep,
  kLocalIndent,
  kLocalEnergy,
  kK11ContactMin,
  kK11ContactMax,
  kK12ContactMin,
  kK12ContactMax,
  kK22ContactMin,
  kK22ContactMax,
  kErrorEstimate,
  kFrameForce,
  kApexMidDeflection,
  // The force's estimated discretisation error, only in runs with mesh.error_estimate:
  // companion (analysis/companion_mesh.hpp).
  kForceError,
  // The failure indices (damage/failure_index.hpp), only in runs whose case monitors the
  // criterion (docs/case-file.md `damage.criteria`).
  kMaxStressIndex,
  kTsaiWuIndex,
  kHashinIndex,
  kDelaminationIndex,
  // The point's stability, only in runs with path.stability: true.
  kStable,
  kLowestEigenvalue,
  kBranch
};

// How path_grid.csv interpolates a column between two converged points (docs/results.md).
enum class GridInterpolation {
  kLinear,
  kHermite,       // cubic Hermite in the depth with the column's depth slopes (a monitor's)
  kHermiteForce,  // the same with the force as slope (the work: dW/dh = T_N)
  // The same where the local energy is zero at both ends (the strain energy without a local
  // law: dU/dh = T_N at equilibrium), linear otherwise.
  kHermiteForceWithoutLocalLaw,
  kMinimum  // the smaller end (a flag: 1 inside only if 1 at both ends)
};

// The runs that write a column (ColumnSpec::group).
enum class ColumnGroup { kEveryRun, kStability, kCompanionMesh };

struct ColumnSpec {
  PathColumn id;
  const char* name;         // "force_N": the column's name in every file
  const char* unit;         // "N", "mm", "1/mm", "-"
  std::string description;  // docs/results.md
  // The value: of the point's state, or (for the run's own columns) of the point.
  double (*of_state)(const IndentationState&) = nullptr;
  double (*of_point)(const PathPoint&) = nullptr;
  void (*restore)(PathPoint&, double) = nullptr;  // the inverse (checkpoints)
  bool monitor = false;  // a continuation monitor (of_state, no assembly needed)
  GridInterpolation grid = GridInterpolation::kLinear;
  // A failure index: present only in the runs that monitor this criterion.
  std::optional<Criterion> criterion = std::nullopt;
  // Which runs write the column: every run, or only those that compute it (path.stability:
  // true; mesh.error_estimate: companion), so that a run without them writes exactly what it
  // wrote before the columns existed.
  ColumnGroup group = ColumnGroup::kEveryRun;
};

// All columns, in path.csv's order (the order of PathColumn).
const std::vector<ColumnSpec>& path_columns();
const ColumnSpec& path_column(PathColumn id);
const char* column_name(PathColumn id);
double column_value(const ColumnSpec& c, const PathPoint& p);

// The columns of a run, in table order: those of every run, the failure index of each
// criterion it monitors, with `stability` (path.stability) the stability columns and with
// `companion` (mesh.error_estimate: companion) the force's error estimate.
// base_columns(): a run without damage (run_columns({})).
std::vector<PathColumn> run_columns(const std::vector<Criterion>& monitored, bool stability = false,
                                    bool companion = false);
// The columns of a result: its monitored criteria's, and the stability and companion columns if
// it has them.
std::vector<PathColumn> result_columns(const PathResult& r);
const std::vector<PathColumn>& base_columns();
// The column of a criterion's failure index.
PathColumn failure_column(Criterion criterion);

// A point's values in the order of `columns`, and the point they restore (its per-node vectors
// empty).
std::vector<double> path_point_values(const PathPoint& p,
                                      const std::vector<PathColumn>& columns = base_columns());
PathPoint path_point_from_values(const std::vector<double>& v,
                                 const std::vector<PathColumn>& columns = base_columns());

// The monitor columns among `columns`, in their order: the continuation's monitors of a run.
std::vector<StateMonitor> path_monitors(const std::vector<PathColumn>& columns = base_columns());
// The monitors among `columns` whose slopes path_grid.csv's Hermite interpolation reads: the
// continuation computes theirs at every point (cont::Settings::slope_monitors), no others'.
std::vector<std::string> slope_monitor_names(const std::vector<PathColumn>& columns);
// Their values at a state, in the same order.
Eigen::VectorXd monitor_values(const IndentationState& s,
                               const std::vector<PathColumn>& columns = base_columns());

}  // namespace si
