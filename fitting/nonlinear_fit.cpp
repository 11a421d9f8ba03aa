#include "fitting/nonlinear_fit.hpp"

#include <nlopt.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fitting/fit_statistics.hpp"
#include "fitting/levenberg_marquardt.hpp"

namespace si::fit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// What the NLopt callback sees (NLopt 2.7.1 takes a function pointer and void*: toolchain.md §5).
// It remembers the best point evaluated, so an exception from NLopt cannot lose it.
struct Objective {
  Evaluator* evaluator = nullptr;
  Eigen::VectorXd scale;
  Eigen::VectorXd best;  // unscaled parameters
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
    // dS/du_j = 2 s_j (J^T r)_j; zero where S is not finite (the line search then backs off).
    Eigen::Map<Eigen::VectorXd> g(grad.data(), grad.size());
    if (std::isfinite(sse))
      g = 2.0 * o.scale.cwiseProduct(o.evaluator->jacobian(c).transpose() * r);
    else
      g.setZero();
  }
  return sse;
}

std::string nlopt_code_name(int code) {
  switch (code) {
    case 1:
      return "SUCCESS";
    case 2:
      return "STOPVAL_REACHED";
    case 3:
      return "FTOL_REACHED";
    case 4:
      return "XTOL_REACHED";
    case 5:
      return "MAXEVAL_REACHED";
    case 6:
      return "MAXTIME_REACHED";
    case -1:
      return "FAILURE";
    case -2:
      return "INVALID_ARGS";
    case -3:
      return "OUT_OF_MEMORY";
    case -4:
      return "ROUNDOFF_LIMITED";
    case -5:
      return "FORCED_STOP";
    default:
      return "code " + std::to_string(code);
  }
}

struct StageOutcome {
  int code = 0;
  std::string name;
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
  try {
    out.code = static_cast<int>(opt.optimize(u, f));
  } catch (const nlopt::roundoff_limited&) {
    out.code = static_cast<int>(nlopt::ROUNDOFF_LIMITED);  // best point kept in `o`
  } catch (const nlopt::forced_stop&) {
    out.code = static_cast<int>(nlopt::FORCED_STOP);
  } catch (const std::invalid_argument&) {
    out.code = static_cast<int>(nlopt::INVALID_ARGS);
  } catch (const std::runtime_error&) {
    out.code = static_cast<int>(nlopt::FAILURE);
  }
  out.name = std::string(algorithm == nlopt::LD_LBFGS ? "LD_LBFGS" : "LN_BOBYQA") + " (" +
             nlopt_code_name(out.code) + ")";
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
  if (!std::isfinite(ev.sum_of_squares(ev.residuals(s.start))))
    throw std::invalid_argument("the residuals are not finite at the starting values");

  FitResult res;
  res.names = problem.parameter_names;
  res.confidence = s.confidence;
  std::string stages;
  StageOutcome stage;
  if (s.method != Method::kDerivativeFree) {
    stage = run_nlopt(nlopt::LD_LBFGS, s, o);
    stages = "NLopt " + stage.name;
  }
  if (s.method == Method::kDerivativeFree ||
      (s.method == Method::kAuto && (stage.code < 0 && stage.code != nlopt::ROUNDOFF_LIMITED))) {
    stage = run_nlopt(nlopt::LN_BOBYQA, s, o);
    stages += (stages.empty() ? "NLopt " : ", fallback ") + stage.name;
  }
  res.nlopt_code = stage.code;
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
    // A quasi-Newton line search can leap onto a plateau where the model no longer depends on
    // some parameters (DanWood from NIST's start 1: b2 -> -6e3, x^b2 = 0). Then, or if the polish
    // did not converge, Levenberg-Marquardt from the start, whose damped steps stay local.
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
