#include "continuation/branch_switching.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "continuation/arclength_stepper.hpp"

namespace si::cont {
namespace {

void check(const Problem& problem, const Event& e, const BranchSwitch& options) {
  const auto n = static_cast<Eigen::Index>(problem.size());
  if (e.type != EventType::kStabilityChange || e.criticality != Criticality::kBifurcation)
    throw std::invalid_argument("switch_branch: the event is a " + e.name + " (" +
                                criticality_name(e.criticality) +
                                "), not a stability_change classified as a bifurcation");
  if (e.x.size() != n || e.mode.size() != n || e.tangent_x.size() != n)
    throw std::invalid_argument(
        "switch_branch: the event has no point, mode or tangent of the problem's size " +
        std::to_string(n) + " (a checkpoint written without x?)");
  if (options.direction != 1 && options.direction != -1)
    throw std::invalid_argument("switch_branch: direction = " + std::to_string(options.direction) +
                                " must be +1 or -1");
  if (!(options.step >= 0.0) || !std::isfinite(options.step))
    throw std::invalid_argument("switch_branch: step = " + std::to_string(options.step) +
                                " must be >= 0 (0 = step_initial)");
}

}  // namespace

Branch switch_branch(Problem& problem, const Event& e, const Settings& settings,
                     const BranchSwitch& options, const Callback& callback) {
  settings.validate();
  check(problem, e, options);
  BorderedSolver bordered(problem, settings.parameter_weight);

  // The mode orthogonalised against the fundamental tangent (the tangent is a unit vector).
  const double along = bordered.inner(e.mode, 0.0, e.tangent_x, e.tangent_p);
  Vector d_x = e.mode - along * e.tangent_x;
  double d_p = -along * e.tangent_p;
  const double norm = std::sqrt(bordered.inner(d_x, d_p, d_x, d_p));
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw std::invalid_argument("switch_branch: the mode is parallel to the branch's tangent");
  d_x *= options.direction / norm;
  d_p *= options.direction / norm;

  Point bifurcation;
  bifurcation.x = e.x;
  bifurcation.p = e.p;
  std::string reason;
  double ds = options.step > 0.0 ? options.step : settings.step_initial;
  for (; ds >= settings.step_min; ds *= 0.5) {
    ArclengthSystem system(problem, bordered, bifurcation, d_x, d_p, ds);
    Vector u = stack(e.x + ds * d_x, e.p + ds * d_p);
    const NewtonResult r = newton_solve(system, u, settings.newton);
    if (!r.converged) {
      reason = r.reason;
      continue;
    }
    ArclengthStepper stepper(problem, bordered, settings);
    const Start start{u.head(e.x.size()), u(e.x.size()), d_x, d_p, options.branch_id};
    return trace(problem, stepper, bordered, start, settings, callback, std::nullopt);
  }
  Branch failed;
  failed.monitor_names = problem.monitor_names();
  failed.status = Status::kStartFailed;
  failed.reason = "no point on the new branch down to step_min: " + reason;
  return failed;
}

}  // namespace si::cont
