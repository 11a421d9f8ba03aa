#include "analysis/indentation_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "analysis/active_set_solver.hpp"
#include "analysis/critical_force.hpp"
#include "analysis/linear_indentation.hpp"
#include "analysis/local_contact.hpp"
#include "contact/indenter_factory.hpp"
#include "continuation/checkpoint.hpp"
#include "continuation/kinsol_corrector.hpp"
#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

IndentationOptions options_of(const CaseFile& c, int threads, const std::string& linear_solver) {
  IndentationOptions o;
  o.linear_solver = linear_solver;
  o.contact_offset = contact_face_offset(c);
  // Every node the indenter can reach within the path's depth, plus a margin for the shell's
  // own motion towards it; adapt() grows the set if contact still spreads past it.
  o.candidate_depth = 1.2 * c.path.depth_max + 1.0;
  o.ncp = c.contact.solver == ContactSolver::kActiveSet ? NcpFunction::kMin
                                                        : NcpFunction::kFischerBurmeisterMin;
  o.threads = threads;
  // The paper's option (issue #4 item 3); the case file refuses it with nonlinear kinematics.
  o.interpolated_traction = c.contact.traction == ContactTraction::kInterpolated;
  o.interpolated.fbar = c.contact.fbar;
  if (c.contact.fbar) o.interpolated.fbar_top = analyze_vam(c.laminate).Fbar_top;
  o.local = local_contact_law(c);
  return o;
}

// The accumulated indenter work and the point, appended to the result.
class PathRecorder {
 public:
  PathRecorder(PathResult& result, const PathCallback& callback)
      : result_(result), callback_(callback) {}
  bool add(IndentationProblem& problem, const cont::Vector& z, double h, int iterations,
           double step, const Eigen::VectorXd& depth_slopes = {}) {
    PathPoint p;
    p.index = static_cast<int>(result_.points.size());
    p.state = problem.evaluate(z, h);
    p.iterations = iterations;
    p.step = step;
    p.depth_slopes = depth_slopes;
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

void finish(PathResult& r, bool completed, const std::string& status, const std::string& reason) {
  r.completed = completed;
  r.status = status;
  r.reason = reason;
}

// Solves the problem at depth h into z (the previous depth's solution on entry); returns why it
// failed, empty on success, and the iterations it took.
using DepthSolve = std::function<std::string(double h, cont::Vector& z, int& iterations)>;

// The depth grid, one solve per depth, from the undeformed start.
PathResult run_depth_grid(IndentationSetup& s, const PathCallback& callback,
                          const std::string& method, const DepthSolve& solve) {
  PathResult r;
  r.method = method;
  r.monitor_names = s.problem->monitor_names();
  PathRecorder rec(r, callback);
  cont::Vector z = s.problem->initial_point();
  if (!rec.add(*s.problem, z, 0.0, 0, 0.0)) {
    finish(r, false, "stopped", "stopped by the user");
    return r;
  }
  double previous = 0;
  for (double h : depth_grid(s.case_file.path)) {
    int iterations = 0;
    const std::string failure = solve(h, z, iterations);
    if (!failure.empty()) {
      finish(r, false, "failed", "depth " + std::to_string(h) + " mm: " + failure);
      return r;
    }
    if (!rec.add(*s.problem, z, h, iterations, h - previous)) {
      finish(r, false, "stopped", "stopped by the user");
      return r;
    }
    previous = h;
  }
  finish(r, true, "completed", "");
  return r;
}

// Linear kinematics: each depth of the grid independently, by the fast path.
PathResult run_linear(IndentationSetup& s, const PathCallback& callback) {
  LinearIndentation fast(*s.problem);
  return run_depth_grid(s, callback, "linear fast path",
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
  return run_depth_grid(
      s, callback, "active_set", [&](double h, cont::Vector& z, int& iterations) -> std::string {
        // Tolerance: 1e-10 of the force a gap of h would carry, as for
        // KINSOL (the force at the start, zero, is no scale).
        const double tol = 1e-10 * std::max(p.force_scale(z), p.stiffness_scale() * h);
        ActiveSetResult a = solve_active_set(p, z, h, tol);
        iterations = a.iterations;
        for (int round = 0; a.converged && round < 10 && p.adapt(z, h); ++round)
          a = solve_active_set(p, z, h, tol);
        return a.converged ? "" : a.reason;
      });
}

cont::Settings continuation_settings(const IndentationSetup& s) {
  const PathSpec& path = s.case_file.path;
  cont::Settings c;
  c.method =
      path.method == PathMethod::kNatural ? cont::Method::kNatural : cont::Method::kPseudoArclength;
  c.step_initial = path.step;
  c.step_min = path.step_min;
  c.step_max = path.step_max;
  c.p_max = path.depth_max;
  c.p_min = -path.depth_max;  // a snap-back may reduce the depth; never below minus the path
  c.max_steps = static_cast<int>(20 * path.depth_max / path.step) + 100;
  c.newton = path_newton_settings(s);
  c.extremum_monitors = {"force_N"};
  // Inflections of T_N against k11, k22 (the critical force) come from the points afterwards
  // (critical_force.hpp): located ones would sit on every contact-set change.
  c.detect_signature_changes = true;
  c.locate_signature_changes = false;  // contact grows node by node: report, do not bisect
  if (c.method == cont::Method::kNatural) c.parameter_values = depth_grid(path);
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

// The run's own part of a checkpoint, beside the library's: the candidate set (append-only, so
// a checkpoint's size tells how much of it applies) and the points written so far.
std::string sidecar_path(const std::string& checkpoint) {
  return checkpoint + ".path.json";
}

void write_sidecar(const std::string& checkpoint, const IndentationProblem& problem,
                   const PathResult& r) {
  nlohmann::json points = nlohmann::json::array();
  for (const PathPoint& p : r.points) points.push_back(path_point_values(p));
  const nlohmann::json j = {{"candidates", problem.candidates()}, {"points", points}};
  write_file_atomically(sidecar_path(checkpoint), j.dump() + "\n");
}

// Restores the candidate set and the points of a checkpointed run; returns the checkpoint.
cont::Checkpoint restore(const std::string& checkpoint, IndentationProblem& problem,
                         PathResult& r) {
  cont::Checkpoint c;
  nlohmann::json side;
  try {
    c = cont::load_checkpoint(checkpoint);
    std::ifstream in(sidecar_path(checkpoint));
    side = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw_input(std::string("cannot resume: ") + e.what(), Where{checkpoint, "", "", 0});
  }
  const std::size_t nc =
      c.state.current.point.x.size() - problem.num_shell_unknowns() - problem.num_local_unknowns();
  std::vector<int> candidates = side["candidates"].get<std::vector<int>>();
  if (nc > candidates.size())
    throw_input("cannot resume: the checkpoint does not belong to this case",
                Where{checkpoint, "", "", 0});
  candidates.resize(nc);
  problem.restore_candidates(candidates);
  const std::size_t kept = std::min(c.branch.points.size(), side["points"].size());
  for (std::size_t i = 0; i < kept; ++i) {
    r.points.push_back(path_point_from_values(side["points"][i].get<std::vector<double>>()));
    r.points.back().index = static_cast<int>(i);
    r.points.back().depth_slopes = depth_slopes(c.branch.points[i]);
  }
  return c;
}

PathResult run_continuation(IndentationSetup& s, const PathCallback& callback,
                            const PathControl& control) {
  PathResult r;
  cont::Settings settings = continuation_settings(s);
  r.method = cont::method_name(settings.method);
  r.monitor_names = s.problem->monitor_names();
  settings.checkpoint_path = control.checkpoint;
  settings.checkpoint_interval = control.checkpoint.empty() ? 0 : control.checkpoint_interval;
  settings.checkpoint_keeps_x = false;  // the points live in the sidecar
  PathRecorder rec(r, callback);
  const cont::Callback on_point = [&](const cont::Point& pt, const cont::Branch&) {
    const bool go_on =
        rec.add(*s.problem, pt.x, pt.p, pt.newton_iterations, pt.step, depth_slopes(pt));
    if (!control.checkpoint.empty()) write_sidecar(control.checkpoint, *s.problem, r);
    return go_on;
  };
  const bool natural = settings.method == cont::Method::kNatural;
  cont::Branch b;
  if (control.resume) {
    const cont::Checkpoint c = restore(control.checkpoint, *s.problem, r);
    b = natural ? cont::natural(*s.problem, c, settings, on_point)
                : cont::pseudo_arclength(*s.problem, c, settings, on_point);
  } else {
    b = natural ? cont::natural(*s.problem, s.problem->initial_point(), 0.0, settings, on_point)
                : cont::pseudo_arclength(*s.problem, s.problem->initial_point(), 0.0, settings,
                                         on_point);
  }
  r.events = b.events;
  const bool ok = b.status == cont::Status::kCompleted || b.status == cont::Status::kReachedBound;
  finish(r, ok, cont::status_name(b.status), b.reason);
  return r;
}

}  // namespace

cont::NewtonSettings path_newton_settings(const IndentationSetup& s) {
  cont::NewtonSettings n;
  n.relative_tolerance = 1e-10;
  // The force a gap of one depth step would carry: the scale of the equilibrium residual.
  n.residual_scale = s.problem->stiffness_scale() * s.case_file.path.step;
  n.max_iterations = 25;
  // KINSOL's step limit is an L2 length over all unknowns, and the multipliers are forces (N):
  // its default, 1000 max(1, |z0|), cuts the Newton steps of a stiff shell short (measured: 2 %
  // residual decrease per iteration on the paper's cap). Allow any step the line search accepts.
  n.max_step = 1e12;
  return n;
}

IndenterPose default_indenter_pose(const CaseFile& c, const ShellModel& model) {
  IndenterPose pose;
  pose.direction = c.indenter.direction;
  pose.axis = c.indenter.axis;
  const int apex = model.apex_node();
  const IndenterSpec& i = c.indenter;
  const double size = std::max({i.radius, i.a, i.b, i.c, i.length});
  // The reference point (centre or tip) above the apex's contact point by twice the indenter's
  // size: clear of the shell; the first touch is found from there (indenter.hpp).
  const Vector3d top = model.mesh.nodes[apex] + contact_face_offset(c) * model.mesh.directors[apex];
  pose.position = c.indenter.position ? *c.indenter.position
                                      : Vector3d(top - (2 * size + 1.0) * pose.direction);
  return pose;
}

IndentationSetup::IndentationSetup(CaseFile c, int threads, const std::string& linear_solver)
    : case_file(std::move(c)), model(build_shell_model(case_file)) {
  pose = default_indenter_pose(case_file, model);
  try {
    indenter = make_indenter(case_file.indenter, pose);
  } catch (const Error& e) {
    throw e.within(Where{case_file.file, "indenter", "", 0});
  }
  try {
    problem = std::make_unique<IndentationProblem>(model, *indenter, pose.direction,
                                                   options_of(case_file, threads, linear_solver));
  } catch (const Error& e) {
    const auto text = [](const Vector3d& v) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "[%g, %g, %g]", v.x(), v.y(), v.z());
      return std::string(buf);
    };
    const std::string where = case_file.indenter.position ? "indenter.position" : "indenter";
    const std::string value = text(pose.position) + " mm, direction " + text(pose.direction);
    // The problem names `indenter`; the case's pose is what the user can change.
    throw Error(e.kind(), e.reason(), Where{case_file.file, where, value, 0});
  }
}

std::vector<double> path_point_values(const PathPoint& p) {
  const IndentationState& s = p.state;
  return {s.depth,
          s.force,
          s.reaction,
          s.apex_deflection,
          s.contact_radius,
          s.contact_area,
          static_cast<double>(s.contact_nodes),
          s.apex_curvature[0],
          s.apex_curvature[1],
          s.apex_curvature[2],
          s.energy,
          p.work,
          s.min_gap,
          s.min_multiplier,
          s.max_complementarity,
          static_cast<double>(p.iterations),
          p.step,
          s.local_indentation,
          s.local_energy,
          s.contact_curvature_min[0],
          s.contact_curvature_max[0],
          s.contact_curvature_min[1],
          s.contact_curvature_max[1],
          s.contact_curvature_min[2],
          s.contact_curvature_max[2]};
}

PathPoint path_point_from_values(const std::vector<double>& v) {
  SI_REQUIRE(v.size() == 25, "a path point has 25 values");
  PathPoint p;
  IndentationState& s = p.state;
  s.depth = v[0], s.force = v[1], s.reaction = v[2], s.apex_deflection = v[3];
  s.contact_radius = v[4], s.contact_area = v[5], s.contact_nodes = static_cast<int>(v[6]);
  s.apex_curvature = Vector3d(v[7], v[8], v[9]);
  s.energy = v[10], p.work = v[11], s.min_gap = v[12], s.min_multiplier = v[13];
  s.max_complementarity = v[14], p.iterations = static_cast<int>(v[15]), p.step = v[16];
  s.local_indentation = v[17], s.local_energy = v[18];
  s.contact_curvature_min = Vector3d(v[19], v[21], v[23]);
  s.contact_curvature_max = Vector3d(v[20], v[22], v[24]);
  return p;
}

std::vector<double> depth_grid(const PathSpec& path) {
  if (!path.depths.empty()) return path.depths;
  std::vector<double> grid;
  const int n = static_cast<int>(std::ceil(path.depth_max / path.step - 1e-9));
  for (int i = 1; i <= n; ++i) grid.push_back(std::min(path.depth_max, i * path.step));
  return grid;
}

PathResult run_indentation_path(IndentationSetup& setup, const PathCallback& callback,
                                const PathControl& control) {
  // A power-law local contact is nonlinear even with linear kinematics: no fast path then.
  const bool fast =
      setup.model.kinematics == Kinematics::kLinear && setup.problem->num_local_unknowns() == 0;
  PathResult r = fast ? run_linear(setup, callback)
                 : setup.case_file.contact.solver == ContactSolver::kActiveSet
                     ? run_active_set(setup, callback)
                     : run_continuation(setup, callback, control);
  for (int k : {0, 2}) {
    const std::vector<cont::Event> found = critical_force_events(r.points, k);
    r.events.insert(r.events.end(), found.begin(), found.end());
  }
  return r;
}

}  // namespace si
