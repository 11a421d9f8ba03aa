#include "analysis/static_run.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/load_problem.hpp"
#include "analysis/mode_field.hpp"
#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "core/decimal_number.hpp"
#include "core/error.hpp"

namespace si {
namespace {

// The continuation settings of a static run (static_run.hpp).
cont::Settings continuation_settings(const StaticSettings& s, double force_scale) {
  cont::Settings c;
  c.newton.relative_tolerance = s.tolerance;
  c.newton.residual_scale = force_scale;
  c.newton.max_iterations = s.max_iterations;
  if (s.method == PathMethod::kNatural) {
    c.method = cont::Method::kNatural;
    const double nominal = 1.0 / s.steps;
    // A hair above the nominal step so that rounding (0.7 + 0.1 < 0.8) cannot leave a step
    // 1e-16 short of a nominal load factor, to be hit by a second, empty step.
    c.step_initial = c.step_max = nominal * (1 + 1e-9);
    c.step_min = s.halve_on_failure ? std::ldexp(nominal, -s.max_halvings) : c.step_initial;
    // Load stepping: a converged step never shortens the next one (only a failure does), and
    // a tangent that turns a lot (a softening structure) is no reason to reject a step.
    c.target_iterations = s.max_iterations;
    c.max_turn_deg = 179;
    for (int i = 1; i <= s.steps; ++i) c.parameter_values.push_back(double(i) / s.steps);
    c.max_steps = std::max(1000, 4 * s.steps);
    return c;
  }
  c.method = cont::Method::kPseudoArclength;
  c.step_initial = s.step;
  c.step_min = s.step_min;
  c.step_max = s.step_max;
  c.parameter_weight = s.parameter_weight;
  c.p_max = s.load_factor_max;
  c.max_steps = s.max_steps;
  return c;
}

// Two modes: shells of revolution lose stability in pairs (cos and sin n theta), and each
// eigenvalue of a pair is then located on itself.
constexpr int kStabilityModes = 2;

// The step result of a point: reactions r = f_int - f_ext at the prescribed dofs
// (assembler.hpp), their sum and that of the applied forces, the recorded displacements.
StepResult step_result(const LoadProblem& problem, const std::vector<int>& record_nodes,
                       LoadPointState s, double lambda, int iterations,
                       std::vector<NodeState>* states) {
  const DofMap& dofs = problem.dofs();
  StepResult result;
  result.load_factor = lambda;
  result.iterations = iterations;
  result.energy = s.energy;
  result.linear_solver = problem.linear_solver();
  const Eigen::VectorXd r = reactions(dofs, s.internal_force, s.external_force);
  result.reactions.resize(dofs.num_prescribed());
  for (int i = 0; i < dofs.num_prescribed(); ++i)
    result.reactions[i] = r[dofs.prescribed_dofs()[i]];
  const int nodes = static_cast<int>(s.states.size());
  for (int n = 0; n < nodes; ++n) {
    result.reaction_force += r.segment<3>(kShellNodeDofs * n);
    result.applied_force += s.external_force.segment<3>(kShellNodeDofs * n);
  }
  for (int n : record_nodes) result.displacements.push_back(s.states[n].u);
  if (states != nullptr) *states = std::move(s.states);
  return result;
}

std::string failure_text(const cont::Branch& branch, const LoadProblem& problem,
                         const StaticSettings& settings) {
  const double last = branch.points.empty() ? 0.0 : branch.points.back().p;
  std::string text;
  if (branch.status == cont::Status::kMaxSteps) {
    text = "the run reached static.max_steps = " + std::to_string(settings.max_steps) +
           " before load factor " + format_decimal(settings.load_factor_max);
  } else {
    text = "no convergence beyond load factor " + format_decimal(last) + ": " + branch.reason;
    if (!problem.last_error().empty()) text += " (last error: " + problem.last_error() + ")";
  }
  return text + "; last converged load factor " + format_decimal(last);
}

}  // namespace

StaticResult run_static(const Mesh& mesh, const DofMap& dofs, const ShellElement& element,
                        const ShellLaw& law, Kinematics kinematics, const Loads& loads,
                        const StaticSettings& settings, const StepCallback& callback, int threads) {
  settings.validate();
  for (int n : settings.record_nodes)
    if (n < 0 || n >= mesh.num_nodes())
      throw_input("recorded node " + std::to_string(n) + " is not in the mesh",
                  Where{"", "static.record_nodes", std::to_string(n), 0});
  LoadProblemOptions options;
  options.kinematics = kinematics;
  // The chart Jacobian of a nonlinear run is unsymmetric (load_problem.hpp).
  options.linear_solver =
      kinematics == Kinematics::kLinear ? settings.linear_solver : LinearSolverKind::kUmfpack;
  options.threads = threads;
  LoadProblem problem(mesh, dofs, element, law, loads, options);
  // Newton's tolerance stays a margin above the residual's roundoff floor (measured on the
  // benchmarks: the floor reaches 10..100 times the estimate; KINSOL's line search stalls there).
  constexpr double kRoundoffMargin = 1000;
  const double scale = std::max(problem.force_scale(),
                                kRoundoffMargin * problem.roundoff_force() / settings.tolerance);
  cont::Settings continuation = continuation_settings(settings, scale);
  if (settings.stability) continuation.stability_modes = kStabilityModes;

  StaticResult out;
  out.state = reference_state(mesh);
  // The events of a step are located before Problem::adapt may re-base the chart at its end
  // (load_problem.hpp): they are read with the base of the point before, the chart at the last
  // callback (copied only when it changes).
  std::vector<NodeState> event_base = problem.chart_base();
  int event_rebasings = problem.rebasings();
  std::size_t events_read = 0;
  const auto read_events = [&](const cont::Branch& branch) {
    for (; events_read < branch.events.size(); ++events_read) {
      const cont::Event& e = branch.events[events_read];
      if (e.x.size() != problem.size()) continue;
      LoadPointState s = event_rebasings == problem.rebasings()
                             ? problem.point_state(e.x, e.p)
                             : problem.point_state_with_base(event_base, e.x, e.p);
      StaticEvent event;
      event.type = e.type;
      event.criticality = e.criticality;
      event.negative_before = e.negative_before;
      event.negative_after = e.negative_after;
      event.at = step_result(problem, settings.record_nodes, std::move(s), e.p, 0,
                             e.type == cont::EventType::kStabilityChange ? &event.states : nullptr);
      if (e.type == cont::EventType::kStabilityChange)
        event.mode = mode_translations(problem.dofs(), e.mode, mesh.num_nodes());
      out.events.push_back(std::move(event));
    }
    if (event_rebasings != problem.rebasings()) {
      event_base = problem.chart_base();
      event_rebasings = problem.rebasings();
    }
  };
  const cont::Callback on_point = [&](const cont::Point& point, const cont::Branch& branch) {
    read_events(branch);
    if (branch.points.size() == 1) return true;  // the start point, lambda = 0
    out.steps.push_back(step_result(problem, settings.record_nodes,
                                    problem.point_state(point.x, point.p), point.p,
                                    point.newton_iterations, &out.state));
    out.steps.back().negative_eigenvalues = point.negative_eigenvalues;
    out.steps.back().stable = point.stable;
    out.steps.back().lowest_eigenvalue = point.lowest_eigenvalue;
    return !callback || callback(out.steps.back(), out.state);
  };
  const cont::Branch branch =
      settings.method == PathMethod::kNatural
          ? cont::natural(problem, problem.initial_point(), 0.0, continuation, on_point)
          : cont::pseudo_arclength(problem, problem.initial_point(), 0.0, continuation, on_point);
  read_events(branch);  // those of a last step that ended the run in adapt()
  switch (branch.status) {
    case cont::Status::kCompleted:
    case cont::Status::kReachedBound:
    case cont::Status::kStoppedByCallback:
      break;
    default:
      out.failure = failure_text(branch, problem, settings);
  }
  return out;
}

}  // namespace si
