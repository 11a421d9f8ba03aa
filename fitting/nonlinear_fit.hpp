// Nonlinear least squares: NLopt minimises S(c) = |r(c)|^2 from the starting values, then a few
// Levenberg-Marquardt iterations (levenberg_marquardt.hpp) polish the result, and the statistics
// come from the Jacobian at the solution (fit_statistics.hpp).
//
// NLopt works on the parameters divided by their scale (|start|, or the bound width, or 1), so
// that all are of order one. The first stage is the gradient method LD_LBFGS with the exact
// gradient 2 J^T r; if it fails (an NLopt error, or no finite point) the derivative-free LN_BOBYQA
// takes over from the start. With Method::kDerivativeFree only LN_BOBYQA is used.
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
