#include "fitting/nonlinear_fit.hpp"

#include <nlopt.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fitting/fit_statistics.hpp"
#include "fitting/levenberg_marquardt.hpp"
#include "fitting/nlopt_status.hpp"

namespace si::fit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// What the NLopt callback sees (NLopt 2.7.1 takes a function pointer and void*: toolchain.md §5).
// It remembers the best point evaluated, so an exception from NLopt cannot lose it.
//
// NLopt minimises S(c) / S(start), not S: the objective and its gradient are then of order one
// whatever the size of the residuals. Without this, NLopt's first gradient step is unit-length
// along -grad S (Luksan's PLIS behind LD_LBFGS takes r = 1 when no minimum estimate is given,
// plis.c), i.e. |grad S| ~ 1e4..1e8 scaled units on NIST's Chwirut2 and Thurber: the trial point
// overflows, ten bisections cannot bring it back, the line search fails twice and LD_LBFGS
// returns FAILURE (docs/fitting.md, "Why LD_LBFGS failed").
struct Objective {
  Evaluator* evaluator = nullptr;
  Eigen::VectorXd scale;
  double normalization = 1.0;  // S(start); NLopt sees S / normalization
  Eigen::VectorXd best;        // unscaled parameters
  double best_sse = kInf;
};

double objective(const std::vector<double>& u, std::vector<double>& grad, void* data) {
  auto& o = *static_cast<Objective*>(data);
  const Eigen::VectorXd c =
      o.scale.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(u.data(), u.size()));
  const Eigen::VectorXd r = o.evaluator->residuals(c);
  const double sse = o.evaluator->sum_of_squares(r);
  if (sse < o.best_sse) {
    o.best_sse = sse;
    o.best = c;
  }
  if (!grad.empty()) {
    // d(S / S0)/du_j = 2 s_j (J^T r)_j / S0; zero where S is not finite (the line search then
    // backs off).
    Eigen::Map<Eigen::VectorXd> g(grad.data(), grad.size());
    if (std::isfinite(sse))
      g = (2.0 / o.normalization) * o.scale.cwiseProduct(o.evaluator->jacobian(c).transpose() * r);
    else
      g.setZero();
  }
  return sse / o.normalization;
}

struct StageOutcome {
  int code = 0;
  std::string name;  // "LD_SLSQP (XTOL_REACHED)"
};

// Runs one NLopt algorithm from `start`; the best point so far stays in `o`.
StageOutcome run_nlopt(nlopt::algorithm algorithm, const FitSettings& s, Objective& o) {
  const int n = static_cast<int>(s.start.size());
  nlopt::opt opt(algorithm, static_cast<unsigned>(n));
  auto scaled = [&](const Eigen::VectorXd& v, double fill) {
    std::vector<double> out(n, fill);
    if (v.size() == n)
      for (int j = 0; j < n; ++j) out[j] = v[j] / o.scale[j];
    return out;
  };
  opt.set_lower_bounds(scaled(s.lower, -HUGE_VAL));
  opt.set_upper_bounds(scaled(s.upper, HUGE_VAL));
  opt.set_min_objective(objective, &o);
  opt.set_xtol_rel(s.xtol_rel);
  opt.set_ftol_rel(s.ftol_rel);
  opt.set_maxeval(s.max_evaluations);
  std::vector<double> u = scaled(s.start, 0.0);
  double f = 0;
  StageOutcome out;
  out.code = optimize_returning_code(opt, u, f);  // the best point is kept in `o`
  out.name = nlopt_algorithm_name(algorithm) + " (" + nlopt_code_name(out.code) + ")";
  return out;
}

void check_settings(const LeastSquaresProblem& p, const FitSettings& s) {
  validate(p);
  const Eigen::Index n = p.num_parameters();
  if (s.start.size() != n)
    throw std::invalid_argument("starting values: " + std::to_string(s.start.size()) +
                                " given for " + std::to_string(n) + " parameters");
  if (!s.start.allFinite()) throw std::invalid_argument("starting values must be finite");
  if (p.num_residuals < n)
    throw std::invalid_argument(std::to_string(n) + " parameters need at least " +
                                std::to_string(n) + " points, got " +
                                std::to_string(p.num_residuals));
  for (const auto* bound : {&s.lower, &s.upper})
    if (bound->size() != 0 && bound->size() != n)
      throw std::invalid_argument("bounds must have one value per parameter");
  for (Eigen::Index j = 0; j < n; ++j) {
    const double lo = s.lower.size() ? s.lower[j] : -kInf;
    const double hi = s.upper.size() ? s.upper[j] : kInf;
    if (!(lo <= s.start[j] && s.start[j] <= hi))
      throw std::invalid_argument("starting value of " + p.parameter_names[j] +
                                  " is outside its bounds");
  }
  if (!(s.confidence > 0.0 && s.confidence < 1.0))
    throw std::invalid_argument("confidence must be between 0 and 1");
}

// Typical size of each parameter: |start|, else the width of finite bounds, else 1.
Eigen::VectorXd parameter_scale(const FitSettings& s) {
  Eigen::VectorXd scale = s.start.cwiseAbs();
  for (Eigen::Index j = 0; j < scale.size(); ++j) {
    if (scale[j] > 0.0) continue;
    const double width = (s.lower.size() && s.upper.size()) ? s.upper[j] - s.lower[j] : kInf;
    scale[j] = std::isfinite(width) && width > 0.0 ? 0.5 * width : 1.0;
  }
  return scale;
}

}  // namespace

FitResult fit(const LeastSquaresProblem& problem, const FitSettings& s) {
  check_settings(problem, s);
  const Eigen::VectorXd scale = parameter_scale(s);
  Evaluator ev(problem, scale);
  Objective o;
  o.evaluator = &ev;
  o.scale = scale;
  o.best = s.start;
  const double sse_start = ev.sum_of_squares(ev.residuals(s.start));
  if (!std::isfinite(sse_start))
    throw std::invalid_argument("the residuals are not finite at the starting values");
  o.normalization = sse_start > 0.0 ? sse_start : 1.0;

  FitResult res;
  res.names = problem.parameter_names;
  res.confidence = s.confidence;
  std::string stages;
  StageOutcome stage;
  if (s.method != Method::kDerivativeFree) {
    stage = run_nlopt(nlopt::LD_SLSQP, s, o);
    stages = "NLopt " + stage.name;
    res.nlopt_algorithm = "LD_SLSQP";
  }
  if (s.method == Method::kDerivativeFree ||
      (s.method == Method::kAuto && is_nlopt_failure(stage.code))) {
    res.nlopt_fallback = s.method == Method::kAuto;
    stage = run_nlopt(nlopt::LN_BOBYQA, s, o);
    stages += (stages.empty() ? "NLopt " : ", fallback ") + stage.name;
    res.nlopt_algorithm = "LN_BOBYQA";
  }
  res.nlopt_code = stage.code;
  res.nlopt_parameters = o.best;
  res.nlopt_sse = o.best_sse;
  res.method = stages;

  Eigen::VectorXd c = o.best;
  bool converged = stage.code > 0 && stage.code != nlopt::MAXEVAL_REACHED;
  res.reason = stages;
  if (s.polish_iterations > 0) {
    LevenbergMarquardtSettings lm;
    lm.max_iterations = s.polish_iterations;
    auto polish = levenberg_marquardt(ev, c, s.lower, s.upper, lm);
    res.method += " + Levenberg-Marquardt polish";
    res.reason += "; Levenberg-Marquardt polish, " + std::to_string(polish.iterations) +
                  " iteration(s): " + polish.reason;
    // A line search can leap onto a plateau where the model no longer depends on some
    // parameters (x^b2 = 0 for b2 -> -inf). Then, or if the polish did not converge,
    // Levenberg-Marquardt from the start, whose damped steps stay local.
    if (!polish.converged || !has_full_column_rank(ev.jacobian(polish.parameters))) {
      auto from_start = levenberg_marquardt(ev, s.start, s.lower, s.upper, lm);
      if (from_start.converged && from_start.sse < polish.sse) {
        polish = from_start;
        res.method += ", restarted from the start";
        res.reason += "; restart of Levenberg-Marquardt from the start, " +
                      std::to_string(polish.iterations) + " iteration(s): " + polish.reason;
      }
    }
    if (polish.sse <= o.best_sse) c = polish.parameters;
    converged = polish.converged;
  }
  res.parameters = c;
  const Eigen::VectorXd r = ev.residuals(c);
  fill_statistics(ev.jacobian(c), r, problem.observed, res);
  res.status = !std::isfinite(ev.sum_of_squares(r)) ? FitStatus::kFailed
               : !converged                         ? FitStatus::kStalled
               : res.rank_deficient                 ? FitStatus::kFailed
                                                    : FitStatus::kConverged;
  if (res.rank_deficient)
    res.reason += "; the Jacobian is rank-deficient at the result: parameters not determined";
  res.at_bound.assign(c.size(), false);
  for (Eigen::Index j = 0; j < c.size(); ++j)
    res.at_bound[j] =
        (s.lower.size() && c[j] == s.lower[j]) || (s.upper.size() && c[j] == s.upper[j]);
  res.evaluations = ev.counts();
  return res;
}

}  // namespace si::fit
