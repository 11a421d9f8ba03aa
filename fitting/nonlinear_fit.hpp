// Nonlinear least squares: NLopt minimises S(c) = |r(c)|^2 from the starting values, then a few
// Levenberg-Marquardt iterations (levenberg_marquardt.hpp) polish the result, and the statistics
// come from the Jacobian at the solution (fit_statistics.hpp).
//
// NLopt works on the parameters divided by their scale (|start|, or the bound width, or 1), so
// that all are of order one, and on S / S(start), so that the objective and its gradient are of
// order one too. The first stage is the gradient method LD_SLSQP (Kraft 1988: quasi-Newton SQP,
// bounds inside its subproblem) with the exact gradient 2 J^T r; if it ends in an NLopt error
// the derivative-free LN_BOBYQA takes over from the start, and the result says so
// (FitResult::nlopt_fallback). With Method::kDerivativeFree only LN_BOBYQA is used. LD_LBFGS was
// the first stage until it was found to fail on unscaled objectives and to stop on plateaus
// (docs/fitting.md, "Why LD_LBFGS failed").
#pragma once

#include <Eigen/Dense>

#include "fitting/fit_result.hpp"
#include "fitting/least_squares_problem.hpp"

namespace si::fit {

enum class Method { kAuto, kGradient, kDerivativeFree };

struct FitSettings {
  Eigen::VectorXd start;         // required, one value per parameter, inside the bounds
  Eigen::VectorXd lower, upper;  // empty: unbounded; else one per parameter (+-inf allowed)
  Method method = Method::kAuto;
  int max_evaluations = 5000;   // budget of the NLopt stage (objective evaluations)
  double xtol_rel = 1e-10;      // NLopt's relative parameter tolerance
  double ftol_rel = 1e-15;      // NLopt's relative tolerance on S
  int polish_iterations = 200;  // Levenberg-Marquardt iterations after NLopt (0: none)
  double confidence = 0.95;     // of the parameter intervals
};

// Throws std::invalid_argument for an inconsistent problem or settings, or residuals that are not
// finite at the start. A numerical failure is reported in the result's status, not thrown.
FitResult fit(const LeastSquaresProblem& problem, const FitSettings& settings);

}  // namespace si::fit
