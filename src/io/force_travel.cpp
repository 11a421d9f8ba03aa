#include "io/force_travel.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/indentation_run.hpp"
#include "continuation/kinsol_corrector.hpp"
#include "core/error.hpp"

namespace si {
namespace {

// The path section that stops at the travels and ends at the last one.
void stop_at(PathSpec& path, const std::vector<double>& travels) {
  path.method = PathMethod::kNatural;
  path.depth_max = travels.back();
  path.depths.clear();
  for (double t : travels)
    if (t > 0.0) path.depths.push_back(t);
  path.step = std::min(path.step, path.depth_max);
  path.step_max = std::max(path.step, std::min(path.step_max, path.depth_max));
  path.step_min = std::min(path.step_min, path.step);
}

bool at_travel(double depth, double t) {
  return std::abs(depth - t) <= 1e-9 * (1 + t);
}

// Each travel solved from the earlier run's state there. False if one does not converge.
bool warm_run(IndentationSetup& setup, const std::vector<double>& travels,
              const ForceTravelStates& warm, const std::function<bool()>& keep_going,
              ForceTravel& out) {
  IndentationProblem& p = *setup.problem;
  if (warm.states.size() != travels.size() || warm.num_shell != p.num_shell_unknowns() ||
      warm.num_local != p.num_local_unknowns())
    return false;
  if (!p.restore_contact(warm.candidates, warm.local_state)) return false;
  const cont::NewtonSettings newton = path_newton_settings(setup);
  std::vector<Eigen::VectorXd> states;
  for (std::size_t k = 0; k < travels.size(); ++k) {
    cont::Vector z = in_present_layout(warm.states[k], p);
    if (z.size() == 0) return false;
    // As the path does: when contact spreads past the candidates, grow them and solve again.
    for (int round = 0;; ++round) {
      const cont::NewtonResult r = cont::solve_at(p, z, travels[k], newton);
      out.newton_iterations += r.iterations;
      if (!r.converged || round == 3) return false;
      if (!p.adapt(z, travels[k])) break;
    }
    out.force.push_back(p.evaluate(z, travels[k]).force);
    states.push_back(z);
    if (keep_going && !keep_going()) return false;
  }
  out.states = {p.candidates(), p.local_state(), std::move(states), p.num_shell_unknowns(),
                p.num_local_unknowns()};
  return true;
}

void cold_run(IndentationSetup& setup, const std::vector<double>& travels,
              const std::function<bool()>& keep_going, ForceTravel& out) {
  std::vector<Eigen::VectorXd> states(travels.size());
  out.force.assign(travels.size(), std::nan(""));
  const PathCallback record = [&](const PathPoint& pt, const cont::Vector& z) {
    for (std::size_t k = 0; k < travels.size(); ++k)
      if (at_travel(pt.state.depth, travels[k]) && states[k].size() == 0) {
        states[k] = z;
        out.force[k] = pt.state.force;
      }
    out.newton_iterations += pt.iterations;
    return !keep_going || keep_going();
  };
  PathControl control;
  control.critical_points = false;  // only the force at the travels is read
  const PathResult r = run_indentation_path(setup, record, control);
  out.ok =
      std::all_of(out.force.begin(), out.force.end(), [](double f) { return std::isfinite(f); });
  if (!out.ok) {
    out.failure = "the path stopped at travel " +
                  std::to_string(r.points.empty() ? 0.0 : r.points.back().state.depth) +
                  " mm, before " + std::to_string(travels.back()) + " mm" +
                  (r.reason.empty() ? "" : ": " + r.reason);
    return;
  }
  const IndentationProblem& p = *setup.problem;
  out.states = {p.candidates(), p.local_state(), std::move(states), p.num_shell_unknowns(),
                p.num_local_unknowns()};
}

}  // namespace

ForceTravel run_force_travel(IndentationCase c, const std::vector<double>& travels, int threads,
                             const std::function<bool()>& keep_going,
                             const ForceTravelStates* warm) {
  ForceTravel out;
  if (travels.empty() || !(travels.back() > 0.0)) {
    out.failure = "no travel to run to";
    return out;
  }
  stop_at(c.path, travels);
  try {
    if (warm != nullptr) {
      IndentationSetup setup(c, threads);
      if (warm_run(setup, travels, *warm, keep_going, out)) {
        out.ok = out.warm = true;
        return out;
      }
      if (keep_going && !keep_going()) {
        out.failure = "interrupted";
        return out;
      }
      out.force.clear();  // the full path from scratch
    }
    IndentationSetup setup(std::move(c), threads);
    cold_run(setup, travels, keep_going, out);
  } catch (const Error& e) {
    out.failure = e.what();
  }
  return out;
}

}  // namespace si
