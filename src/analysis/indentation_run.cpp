#include "analysis/indentation_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>

#include "analysis/critical_force.hpp"
#include "analysis/critical_points.hpp"
#include "analysis/local_contact.hpp"
#include "analysis/path_columns.hpp"
#include "contact/indenter_factory.hpp"
#include "continuation/branch_switching.hpp"
#include "continuation/brent_root.hpp"
#include "continuation/checkpoint.hpp"
#include "continuation/kinsol_corrector.hpp"
#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "indentation/active_set_solver.hpp"
#include "indentation/linear_indentation.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

// A point's stability as the continuation computed it; negative = -1: not computed.
struct PointStability {
  int negative = -1;
  bool stable = false;
  double lowest = std::nan("");
};

PointStability stability_of(const cont::Point& pt) {
  return {pt.negative_eigenvalues, pt.stable, pt.lowest_eigenvalue};
}

// The accumulated indenter work and the point, appended to the result. With path.stability
// (result.stability), a point the continuation did not analyse (the depth grids') is analysed
// here.
class PathRecorder {
 public:
  PathRecorder(PathResult& result, const PathCallback& callback)
      : result_(result), callback_(callback) {}
  bool add(IndentationProblem& problem, const cont::Vector& z, double h, int iterations,
           double step, const Eigen::VectorXd& depth_slopes = {}, PointStability stability = {},
           int branch = 0) {
    PathPoint p;
    p.index = static_cast<int>(result_.points.size());
    p.branch = branch;
    p.state = problem.evaluate(z, h);
    p.iterations = iterations;
    p.step = step;
    p.depth_slopes = depth_slopes;
    if (result_.stability && stability.negative < 0) {
      cont::Stability s;
      if (problem.stability(z, h, 1, s))
        stability = {s.negative, s.negative == 0 && s.zero == 0, s.eigenvalues[0]};
    }
    p.negative_eigenvalues = stability.negative;
    p.stable = stability.stable;
    p.lowest_eigenvalue = stability.lowest;
    if (!result_.points.empty()) {
      const IndentationState& prev = result_.points.back().state;
      p.work = result_.points.back().work +
               0.5 * (prev.force + p.state.force) * (p.state.depth - prev.depth);
    }
    result_.points.push_back(p);
    return !callback_ || callback_(result_.points.back(), z);
  }

 private:
  PathResult& result_;
  const PathCallback& callback_;
};

void finish(PathResult& r, bool completed, RunStatus status, const std::string& reason) {
  r.completed = completed;
  r.status = status;
  r.reason = reason;
}

// Solves the problem at depth h into z (the previous depth's solution on entry); returns why it
// failed, empty on success, and the iterations it took.
using DepthSolve = std::function<std::string(double h, cont::Vector& z, int& iterations)>;

// A trial depth of an onset's search on a grid: its solved state.
struct OnsetTrial {
  cont::Vector z;
  IndentationState state;
};

// Onset events between the last two points of a grid: where a failure index reaches 1. With an
// exact solve per depth (`solve`, the linear fast path) located by Brent's method
// (continuation/brent_root.hpp) to an index within kOnsetIndexTolerance of 1, as the
// continuation's onsets, or a 1e-10 bracket; otherwise (the active-set grid, whose solves may
// grow the candidate set) interpolated linearly and marked not located.
void locate_onsets(IndentationSetup& s, PathResult& r, const cont::Vector& z_previous,
                   const DepthSolve& solve) {
  using Sample = cont::RootSample<OnsetTrial>;
  const PathPoint& a = r.points[r.points.size() - 2];
  const PathPoint& b = r.points.back();
  const std::vector<PathColumn> columns = result_columns(r);
  for (Criterion c : r.criteria) {
    const int k = static_cast<int>(c);
    const double fa = a.state.failure[k].index - 1;
    const double fb = b.state.failure[k].index - 1;
    if (!(fa < 0 && fb >= 0)) continue;
    cont::Event e;
    e.type = cont::EventType::kZeroCrossing;
    e.monitor = column_name(failure_column(c));
    e.step = b.index;
    e.p = a.state.depth + (b.state.depth - a.state.depth) * fa / (fa - fb);
    e.accuracy = b.state.depth - a.state.depth;
    e.monitors = monitor_values(b.state, columns);
    e.located = false;
    bool failed = false;
    const auto evaluate = [&](double& h, const Sample&, const Sample&, OnsetTrial& at, double& f) {
      at.z = z_previous;
      int iterations = 0;
      failed = !solve(h, at.z, iterations).empty();
      if (failed) return false;
      at.state = s.problem->evaluate(at.z, h);
      f = at.state.failure[k].index - 1;
      return true;
    };
    const cont::RootSearch search{1e-10 * (1 + b.state.depth), kOnsetIndexTolerance, 60};
    if (solve) {
      const cont::RootBracket<OnsetTrial> root = cont::brent_root<OnsetTrial>(
          {a.state.depth, fa, {}}, {b.state.depth, fb, {}}, search, evaluate);
      // The bracket's ends are the grid's points, whose states are not trials: only a trial
      // (a solved state) is an event point.
      if (!failed && root.best.at.z.size() > 0) {
        e.p = root.best.x;
        e.x = root.best.at.z;
        e.monitors = monitor_values(root.best.at.state, columns);
        e.accuracy = std::min(root.width(), root.secant_distance());
        e.located = root.converged(search);
      }
    }
    r.events.push_back(e);
  }
}

// The stability changes between the points of a depth grid, not located (no continuation to
// bisect along): one event per change of the negative count, at the later point.
std::vector<cont::Event> grid_stability_events(const PathResult& r) {
  std::vector<cont::Event> events;
  for (std::size_t i = 1; i < r.points.size(); ++i) {
    const PathPoint &a = r.points[i - 1], &b = r.points[i];
    if (a.negative_eigenvalues < 0 || b.negative_eigenvalues < 0 ||
        a.negative_eigenvalues == b.negative_eigenvalues)
      continue;
    cont::Event e;
    e.type = cont::EventType::kStabilityChange;
    e.name = cont::event_type_name(e.type);
    e.p = b.state.depth;
    e.monitors = monitor_values(b.state, result_columns(r));
    e.step = static_cast<int>(i);
    e.accuracy = b.state.depth - a.state.depth;
    e.negative_before = a.negative_eigenvalues;
    e.negative_after = b.negative_eigenvalues;
    events.push_back(e);
  }
  return events;
}

// The depth grid, one solve per depth, from the undeformed start.
PathResult run_depth_grid(IndentationSetup& s, const PathCallback& callback, RunMethod method,
                          const DepthSolve& solve) {
  PathResult r;
  r.method = method;
  r.stability = s.spec.path.stability;
  r.monitor_names = s.problem->monitor_names();
  r.criteria = monitored_criteria(s.spec);
  PathRecorder rec(r, callback);
  cont::Vector z = s.problem->initial_point();
  r.final_unknowns = z;
  if (!rec.add(*s.problem, z, 0.0, 0, 0.0)) {
    finish(r, false, RunStatus::kStopped, "stopped by the user");
    return r;
  }
  double previous = 0;
  for (double h : depth_grid(s.spec.path)) {
    int iterations = 0;
    const std::string failure = solve(h, z, iterations);
    if (!failure.empty()) {
      finish(r, false, RunStatus::kFailed, "depth " + std::to_string(h) + " mm: " + failure);
      return r;
    }
    const cont::Vector z_previous = r.final_unknowns;
    r.final_unknowns = z;
    if (!rec.add(*s.problem, z, h, iterations, h - previous)) {
      finish(r, false, RunStatus::kStopped, "stopped by the user");
      return r;
    }
    locate_onsets(s, r, z_previous, method == RunMethod::kLinearFastPath ? solve : DepthSolve());
    previous = h;
  }
  // Beside the onsets found on the way, in depth order.
  const std::vector<cont::Event> changes = grid_stability_events(r);
  r.events.insert(r.events.end(), changes.begin(), changes.end());
  std::stable_sort(r.events.begin(), r.events.end(),
                   [](const cont::Event& a, const cont::Event& b) { return a.p < b.p; });
  finish(r, true, RunStatus::kCompleted, "");
  return r;
}

// Linear kinematics: each depth of the grid independently, by the fast path.
PathResult run_linear(IndentationSetup& s, const PathCallback& callback) {
  LinearIndentation fast(*s.problem);
  return run_depth_grid(s, callback, RunMethod::kLinearFastPath,
                        [&](double h, cont::Vector& z, int& iterations) -> std::string {
                          try {
                            z = fast.solve(h);
                          } catch (const Error& e) {
                            if (e.kind() != ErrorKind::kNumerical) throw;
                            return e.reason();
                          }
                          iterations = fast.last_iterations();
                          return "";
                        });
}

// contact.solver active_set: the primal-dual active-set method at each depth of the grid,
// solved again while the candidate set grows (as the continuation library does).
PathResult run_active_set(IndentationSetup& s, const PathCallback& callback) {
  IndentationProblem& p = *s.problem;
  return run_depth_grid(s, callback, RunMethod::kActiveSet,
                        [&](double h, cont::Vector& z, int& iterations) -> std::string {
                          // Tolerance: 1e-10 of the force a gap of h would carry, as for
                          // KINSOL (the force at the start, zero, is no scale).
                          const double tol =
                              1e-10 * std::max(p.force_scale(z), p.stiffness_scale() * h);
                          ActiveSetResult a = solve_active_set(p, z, h, tol);
                          iterations = a.iterations;
                          for (int round = 0; a.converged && round < 10 && p.adapt(z, h); ++round)
                            a = solve_active_set(p, z, h, tol);
                          return a.converged ? "" : a.reason;
                        });
}

// The run's status for the continuation's, in cont::Status's order (continuation/branch.hpp).
RunStatus run_status(cont::Status s) {
  static_assert(static_cast<int>(cont::Status::kStartFailed) == 6, "cont::Status changed");
  constexpr RunStatus kByStatus[] = {RunStatus::kFailed,  // kRunning: never returned
                                     RunStatus::kCompleted, RunStatus::kReachedBound,
                                     RunStatus::kMaxSteps,  RunStatus::kStepTooSmall,
                                     RunStatus::kStopped,   RunStatus::kStartFailed};
  return kByStatus[static_cast<int>(s)];
}

cont::Settings continuation_settings(const IndentationSetup& s) {
  const PathSpec& path = s.spec.path;
  cont::Settings c;
  c.method =
      path.method == PathMethod::kNatural ? cont::Method::kNatural : cont::Method::kPseudoArclength;
  c.step_initial = path.step;
  c.step_min = path.step_min;
  c.step_max = path.step_max;
  c.p_max = path.depth_max;
  c.p_min = -path.depth_max;  // a snap-back may reduce the depth; never below minus the path
  c.max_steps = static_cast<int>(20 * path.depth_max / path.step) + 100;
  c.target_iterations = path.target_iterations;
  // Away from a snap-back the depth is the branch's dominant coordinate (|dh/ds| of 0.97-0.99
  // on the paper's cap): correcting at the predictor's depth needs one Krylov solve per Newton
  // iteration instead of the bordered system's two (docs/performance.md, 2026-11-30).
  c.natural_corrector_slope = 0.5;
  c.newton = path_newton_settings(s);
  c.extremum_monitors = {column_name(PathColumn::kForce)};
  c.slope_monitors = slope_monitor_names(run_columns(monitored_criteria(s.spec)));
  // Damage onset: each monitored failure index reaching 1 (analysis/damage_results.hpp).
  if (s.spec.damage)
    for (Criterion k : s.spec.damage->criteria)
      c.level_crossings.push_back({column_name(failure_column(k)), 1.0, kOnsetIndexTolerance});
  // Inflections of T_N against k11, k22 (the critical force) come from the points afterwards,
  // by the curve-feature rules (critical_force.hpp). The library's located ones (inflections)
  // re-solve inside every step with a resolved sign change and evaluate second derivatives at
  // every point: measured 5.8 times the main job's time, and the re-solves change the solver's
  // warm state (the path's last bits, at the 1e-10 tolerance).
  c.detect_signature_changes = true;
  c.locate_signature_changes = false;  // contact grows node by node: report, do not bisect
  // natural stops at every depth of the grid; pseudo-arclength lands on the requested depths
  // (path.depths) on its way to depth_max, its grid being interpolated (path_grid.csv).
  c.parameter_values = c.method == cont::Method::kNatural ? depth_grid(path) : path.depths;
  // The lowest mode: a change of the count by more than one is located by bisection on it.
  c.stability_modes = path.stability ? 1 : 0;
  return c;
}

// The monitors' derivatives in the depth at a continuation point: their slopes along the branch
// over the depth's, d m / d s / (d h / d s); NaN near a fold (|dh/ds| < 1e-3 of the unit
// tangent), where the depth is no parameter of the branch.
Eigen::VectorXd depth_slopes(const cont::Point& pt) {
  if (pt.monitor_slopes.size() == 0) return {};
  if (!(std::abs(pt.tangent_p) > 1e-3))
    return Eigen::VectorXd::Constant(pt.monitor_slopes.size(), std::nan(""));
  return pt.monitor_slopes / pt.tangent_p;
}

// The run's own part of a checkpoint, saved by the library in the same file: the candidate set,
// the points so far and the caller's record.
nlohmann::json path_attachment(const IndentationProblem& problem, const PathResult& r,
                               const PathControl& control) {
  nlohmann::json points = nlohmann::json::array();
  for (const PathPoint& p : r.points) points.push_back(path_point_values(p, result_columns(r)));
  return {{"candidates", problem.candidates()},
          {"local_state", problem.local_state()},
          {"points", points},
          {"record", control.save_record ? control.save_record() : nlohmann::json()}};
}

// Restores the caller's record, the candidate set and the points of a checkpointed run; returns
// the checkpoint.
cont::Checkpoint restore(const PathControl& control, IndentationProblem& problem, PathResult& r) {
  const Where where{control.checkpoint, "", "", 0};
  cont::Checkpoint c;
  try {
    c = cont::load_checkpoint(control.checkpoint);
  } catch (const std::exception& e) {
    throw_input(std::string("cannot resume: ") + e.what(), where);
  }
  const nlohmann::json& a = c.attachment;
  if (!a.is_object() || !a.contains("points") || !a.contains("candidates"))
    throw_input(
        "cannot resume: the checkpoint holds no path record (written by an older shellindent?); "
        "run again without --resume",
        where);
  if (control.restore_record) control.restore_record(a.value("record", nlohmann::json()));
  const std::size_t nc =
      c.state.current.point.x.size() - problem.num_shell_unknowns() - problem.num_local_unknowns();
  std::vector<int> candidates = a["candidates"].get<std::vector<int>>();
  const nlohmann::json local = a.value("local_state", nlohmann::json::array());
  const bool numbers = local.is_array() && std::all_of(local.begin(), local.end(),
                                                       [](const auto& v) { return v.is_number(); });
  if (nc != candidates.size() || a["points"].size() != c.branch.points.size() || !numbers ||
      !problem.restore_contact(candidates, local.get<std::vector<double>>()))
    throw_input("cannot resume: the checkpoint does not belong to this case", where);
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    r.points.push_back(
        path_point_from_values(a["points"][i].get<std::vector<double>>(), result_columns(r)));
    r.points.back().negative_eigenvalues = c.branch.points[i].negative_eigenvalues;
    r.points.back().index = static_cast<int>(i);
    r.points.back().depth_slopes = depth_slopes(c.branch.points[i]);
  }
  return c;
}

// Why a continuation run ended, in the path's terms: "reached depth_max 10 mm" rather than the
// library's "p reached the bound 10".
std::string end_reason(const cont::Branch& b, const PathSpec& path) {
  if (b.status != cont::Status::kReachedBound || b.points.empty()) return b.reason;
  const double depth = b.points.back().p;
  return depth > 0 ? "reached depth_max " + format_quantity(path.depth_max, Dimension::kLength)
                   : "reached the lower bound of the depth, -depth_max = " +
                         format_quantity(-path.depth_max, Dimension::kLength);
}

// Where a branch ends under path.branch_switch: the fundamental branch at its first bifurcation;
// a switched one where it meets another branch: at a stability change, or at a fold of the depth
// (a branch that leaves one bifurcation of a symmetric path and arrives at another, like the
// hinged roof's, turns back there with the eigenvalue touching zero on both sides: a pitchfork
// seen from the new branch, no change of stability). nullptr if none yet.
const cont::Event* first_change(const cont::Branch& b, bool fundamental) {
  for (const cont::Event& e : b.events) {
    if (e.type == cont::EventType::kStabilityChange &&
        (!fundamental || e.criticality == cont::Criticality::kBifurcation))
      return &e;
    if (!fundamental && e.type == cont::EventType::kLimitPoint) return &e;
  }
  return nullptr;
}

// path.branch_switch after the fundamental branch stopped at its first bifurcation `at`: the new
// branch from there (continuation/branch_switching.hpp), its points and events appended to r
// (event steps counted in r's points), until it meets a stability change or a bound.
void follow_switched_branch(IndentationSetup& s, const cont::Settings& settings,
                            const cont::Event* at, const BranchSwitchSpec& spec,
                            const cont::Callback& on_point, PathResult& r) {
  const int before = static_cast<int>(r.points.size());
  cont::BranchSwitch options;
  options.direction = spec.direction;
  const cont::Branch n = cont::switch_branch(*s.problem, *at, settings, options, on_point);
  for (cont::Event e : n.events) {
    e.step += before;
    r.events.push_back(std::move(e));
  }
  if (!n.points.empty() && n.points.back().x.size() > 0) r.final_unknowns = n.points.back().x;
  const cont::Event* end = first_change(n, false);
  const std::string from =
      "branch 1 from the bifurcation at depth " + format_quantity(at->p, Dimension::kLength);
  if (end)
    finish(r, true, RunStatus::kCompleted,
           from + " to where it meets another branch (" + cont::event_type_name(end->type) +
               (end->type == cont::EventType::kLimitPoint ? " of the depth" : "") + ") at depth " +
               format_quantity(end->p, Dimension::kLength));
  else
    finish(r, n.status == cont::Status::kReachedBound, run_status(n.status),
           from + ": " + end_reason(n, s.spec.path));
}

PathResult run_continuation(IndentationSetup& s, const PathCallback& callback,
                            const PathControl& control) {
  PathResult r;
  r.stability = s.spec.path.stability;
  cont::Settings settings = continuation_settings(s);
  r.method =
      settings.method == cont::Method::kNatural ? RunMethod::kNatural : RunMethod::kPseudoArclength;
  r.monitor_names = s.problem->monitor_names();
  r.criteria = monitored_criteria(s.spec);
  settings.checkpoint_path = control.checkpoint;
  settings.checkpoint_writer = [](const std::string& path, const std::string& text) {
    write_file_atomically(path, text);
  };
  settings.checkpoint_interval = control.checkpoint.empty() ? 0 : control.checkpoint_interval;
  settings.checkpoint_keeps_x = false;  // the points live in the attachment
  settings.checkpoint_attachment = [&] { return path_attachment(*s.problem, r, control); };
  settings.on_step_failure = control.on_step_failure;
  PathRecorder rec(r, callback);
  // path.branch_switch: the fundamental branch ends at its first bifurcation (the point past it,
  // on the fundamental branch, is not kept), the switched one where it meets another branch
  // (first_change).
  const std::optional<BranchSwitchSpec> switching = s.spec.path.branch_switch;
  if (switching) settings.checkpoint_interval = 0;  // a resume could not tell the branches apart
  const cont::Callback on_point = [&](const cont::Point& pt, const cont::Branch& branch) {
    if (switching && first_change(branch, pt.branch_id == 0)) return false;
    return rec.add(*s.problem, pt.x, pt.p, pt.newton_iterations, pt.step, depth_slopes(pt),
                   stability_of(pt), pt.branch_id);
  };
  const bool natural = settings.method == cont::Method::kNatural;
  cont::Branch b;
  if (control.resume) {
    const cont::Checkpoint c = restore(control, *s.problem, r);
    r.final_unknowns = c.state.current.point.x;  // the last point, unless the run goes on
    b = natural ? cont::natural(*s.problem, c, settings, on_point)
                : cont::pseudo_arclength(*s.problem, c, settings, on_point);
  } else {
    b = natural ? cont::natural(*s.problem, s.problem->initial_point(), 0.0, settings, on_point)
                : cont::pseudo_arclength(*s.problem, s.problem->initial_point(), 0.0, settings,
                                         on_point);
  }
  r.events = b.events;
  r.checkpointed_points = b.checkpointed;
  if (!b.points.empty() && b.points.back().x.size() > 0) r.final_unknowns = b.points.back().x;
  const bool ok = b.status == cont::Status::kCompleted || b.status == cont::Status::kReachedBound;
  finish(r, ok, run_status(b.status), end_reason(b, s.spec.path));
  if (!switching) return r;
  if (const cont::Event* at = first_change(b, true))
    follow_switched_branch(s, settings, at, *switching, on_point, r);
  else if (ok)
    r.reason += "; path.branch_switch: no bifurcation on the path, no branch to switch to";
  return r;
}
}  // namespace

PathResult run_indentation_path(IndentationSetup& setup, const PathCallback& callback,
                                const PathControl& control) {
  // A power-law local contact is nonlinear even with linear kinematics, and the fast path knows
  // the indenter's rows only (not a support frame's): no fast path then.
  const bool fast = setup.model.kinematics == Kinematics::kLinear &&
                    setup.problem->num_local_unknowns() == 0 && !setup.problem->support_frame();
  // The onset of nonlinearity's bracket start is kept on the way (critical_points.hpp).
  const std::shared_ptr<OnsetWatch> watch = control.critical_points ? watch_onset(setup) : nullptr;
  const PathCallback watched = watching(watch, callback);
  // The first step starts from the twin's state at its depth (6 -> 2 Newton iterations on the
  // 1e5-unknown cap: docs/performance.md).
  setup.problem->set_first_step_start(first_step_from_twin(watch, *setup.problem));
  PathResult r = fast ? run_linear(setup, watched)
                 : setup.spec.contact.solver == ContactSolver::kActiveSet
                     ? run_active_set(setup, watched)
                     : run_continuation(setup, watched, control);
  setup.problem->set_first_step_start(nullptr);
  for (int k : {0, 2}) {
    const std::vector<cont::Event> found = critical_force_events(r.points, k);
    r.events.insert(r.events.end(), found.begin(), found.end());
  }
  add_damage_results(setup, r);
  if (control.critical_points) r.critical = find_critical_points(setup, r, watch.get());
  return r;
}

}  // namespace si
