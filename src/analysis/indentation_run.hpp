// A depth path of an indentation case, end to end: the model, the indenter at its pose, the contact
// problem, and the path method (docs/case-file.md `path`, `contact`):
//  * linear kinematics: the linear fast path (linear_indentation.hpp) at each depth of the grid
//    - exact for the linear problem, which has no limit points, so `path.method` is not needed;
//    with a power-law local contact (contact.local hertz or yang_sun, nonlinear) the path is
//    that of the nonlinear kinematics below, on the linear problem;
//  * nonlinear, contact.solver kinsol: continuation/ natural (the depth grid, hit exactly) or
//    pseudo_arclength (to depth_max, through limit points), with the KINSOL corrector on the
//    Fischer-Burmeister system, events located (force extrema, inflections of T_N against k11
//    and k22 - the paper's critical force -, limit points of the depth, contact-set changes);
//  * nonlinear, contact.solver active_set: the primal-dual active-set method at each depth of the
//    grid (the cross-check solver, active_set_solver.hpp).
// The depth grid is path.depths, or 0, step, 2 step, ..., depth_max.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/critical_point.hpp"
#include "analysis/damage_probe.hpp"
#include "analysis/damage_results.hpp"
#include "analysis/imperfection_seed.hpp"
#include "analysis/indentation_case.hpp"
#include "continuation/branch.hpp"
#include "continuation/settings.hpp"
#include "indentation/indentation_problem.hpp"
#include "model/shell_model.hpp"

namespace si {

// Model, indenter and contact problem of a case, kept together (the problem refers to both).
struct IndentationSetup {
  IndentationCase spec;
  ShellModel model;
  IndenterPose pose;
  std::unique_ptr<Indenter> indenter;
  std::unique_ptr<IndentationProblem> problem;
  // The failure indices at the nodes near the indenter (a case whose `damage:` section names
  // criteria); the problem's probe.
  std::shared_ptr<const DamageProbe> damage;
  // path.imperfection: where the mode came from and the translations added to model.mesh
  // (imperfection_seed.hpp); none for a perfect shell.
  std::optional<ImperfectionSeed> imperfection;

  // Throws an input error naming the case file and key for a case that cannot run.
  // linear_solver: the contact Jacobian's solver (indentation_problem.hpp, docs/performance.md).
  IndentationSetup(IndentationCase c, int threads,
                   JacobianSolverKind linear_solver = JacobianSolverKind::kPreconditionedKrylov);
};

// The indenter's pose: the case's indenter.position/direction/axis; without a position, the
// reference point starts on the apex's line of travel, clear of the shell.
IndenterPose default_indenter_pose(const IndentationCase& c, const ShellModel& model);

struct PathPoint {
  int index = 0;  // position on the path (0 = the start point)
  IndentationState state;
  int iterations = 0;  // corrector (Newton / active-set) iterations that produced the point
  double step = 0;     // step that produced it (depth for grids, arclength for pseudo_arclength)
  double work = 0;     // indenter work so far, trapezoidal integral of force over depth, N mm
  // d(monitor)/d(depth) along the branch, one per PathResult::monitor_names (continuation runs;
  // NaN where the branch is nearly vertical in depth, at a fold); empty where unknown.
  Eigen::VectorXd depth_slopes;
  // path.stability: the tangent restricted to the active contacts (IndentationProblem::stability)
  // - its number of negative eigenvalues (-1: not computed), stable (none negative or zero), and
  // its lowest eigenvalue (N/mm in the shell's chart coordinates).
  int negative_eigenvalues = -1;
  // The branch the point lies on: 0 the fundamental path, 1 the one switched to at its first
  // bifurcation (path.branch_switch).
  int branch = 0;
  bool stable = false;
  // mesh.error_estimate: companion - the force's estimated relative discretisation error
  // (companion_mesh.hpp); NaN where the companion has no point at this depth.
  double force_error = std::nan("");
  double lowest_eigenvalue = std::nan("");
};

// How a path was computed (see the header): the linear fast path, the active-set grid, or a
// continuation method.
enum class RunMethod { kLinearFastPath, kActiveSet, kNatural, kPseudoArclength };

// How a run ended. kCompleted and kReachedBound reached the end of the path; kStopped: the
// callback asked (Ctrl-C); kFailed: a depth of a grid could not be solved; the others are the
// continuation's (continuation/branch.hpp Status).
enum class RunStatus {
  kCompleted,
  kReachedBound,
  kMaxSteps,
  kStepTooSmall,
  kStopped,
  kStartFailed,
  kFailed
};

struct PathResult {
  RunMethod method = RunMethod::kPseudoArclength;
  std::vector<PathPoint> points;
  std::vector<cont::Event> events;
  std::vector<std::string> monitor_names;
  std::vector<Criterion> criteria;  // monitored: their failure-index columns are the run's
  DamageResults damage;             // a case with a `damage:` section (damage_results.hpp)
  bool completed = false;           // reached the end of the path
  RunStatus status = RunStatus::kFailed;
  std::string reason;  // why it stopped early; empty when completed
  // How many of `points` the run's checkpoint file holds: `--resume` continues from
  // points[checkpointed_points - 1] (a stopped run keeps its last periodic checkpoint). 0: none.
  std::size_t checkpointed_points = 0;
  // The problem's unknowns at the last point (to write its fields); empty if there is none.
  cont::Vector final_unknowns;
  // path.stability: every point has its stability, and the results carry its columns.
  bool stability = false;
  // mesh.error_estimate: companion: every point has its force_error (companion_mesh.hpp), and
  // the results carry its column.
  bool companion_mesh = false;
  // The named critical points (critical_points.hpp; PathControl::critical_points).
  CriticalPoints critical;
};

// Called after each accepted point with the point and the problem's unknowns; returning false
// stops the run (RunStatus::kStopped, every converged point kept).
using PathCallback = std::function<bool(const PathPoint&, const cont::Vector& z)>;

// Checkpoints and resume (continuation methods only; the linear fast path and the active-set
// grid are not resumable - they are fast or independent per depth and simply rerun).
struct PathControl {
  // The continuation library's checkpoint file, written every checkpoint_interval points and at
  // the end (not when the callback stopped the run: the last periodic one is kept). It holds,
  // in the same atomic write, the candidate set, the points and the caller's record, so a kill
  // at any instant leaves them in step. Empty: no checkpoints.
  std::string checkpoint;
  int checkpoint_interval = 10;
  // Continue from `checkpoint` (same case): the points up to it are kept, the path goes on
  // from its state and repeats the uninterrupted run bit for bit (the solver caches are dropped
  // at every checkpoint, cont::Problem::reset_solver_caches).
  bool resume = false;
  // The caller's own record (e.g. the CLI's case digest and VTU frames), saved with each
  // checkpoint, and handed back on resume before the run goes on (it may throw to refuse).
  std::function<nlohmann::json()> save_record;
  std::function<void(const nlohmann::json&)> restore_record;
  // Find the named critical points after the run (PathResult::critical; for the onset of
  // nonlinearity a linear-kinematics twin of the case, solved by the fast path at each point's
  // depth). A calibration's force-travel runs read only the force and skip them.
  bool critical_points = true;
  // Told of each failed continuation step as it happens (cont::Settings::on_step_failure; p is
  // the depth in mm). Empty: none.
  std::function<void(const cont::StepFailure&)> on_step_failure;
};

// The Newton settings of a continuation run's corrector, for solves at a fixed depth outside a
// path (io/force_travel.hpp's warm starts).
cont::NewtonSettings path_newton_settings(const IndentationSetup& setup);

// An earlier state in the problem's present layout: shell unknowns, the multipliers of the
// candidates it knew (the set only grows, so they come first), zeros for the candidates added
// since, the local approach last; empty if it cannot be one of this problem's.
cont::Vector in_present_layout(const Eigen::VectorXd& old, const IndentationProblem& problem);

// Runs the path. Numerical failures do not throw: they end the path with the reason.
PathResult run_indentation_path(IndentationSetup& setup, const PathCallback& callback = {},
                                const PathControl& control = {});

}  // namespace si
