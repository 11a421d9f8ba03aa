// Levenberg-Marquardt iterations on a least-squares problem, used to polish what NLopt returns:
// minimising the sum of squares with a quasi-Newton method stalls a few digits short on badly
// scaled problems (NIST's Thurber, Misra1a), while Gauss-Newton steps on the residuals themselves
// converge quadratically near a small-residual minimum.
//
// Each step solves min |[J; sqrt(lambda) D] d + [r; 0]| by QR (never the normal equations, whose
// condition number is the square of J's), with D the running maximum of J's column norms (Moré
// 1978, "The Levenberg-Marquardt algorithm: implementation and theory", eq. 6.3), so the
// iteration is invariant to the scaling of the parameters. Steps leaving the bounds are
// projected onto them.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "fitting/least_squares_problem.hpp"

namespace si::fit {

struct LevenbergMarquardtSettings {
  int max_iterations = 200;
  double xtol_rel = 1e-12;      // converged when |D step| <= xtol_rel |D c| (Moré 1978, D below)
  double gradient_tol = 1e-10;  // ... or when cos(r, J e_j) <= this for all j (MINPACK's gtol)
};

struct LevenbergMarquardtOutcome {
  Eigen::VectorXd parameters;
  double sse = 0;
  int iterations = 0;
  bool converged = false;
  std::string reason;
};

// lower/upper: empty (unbounded) or one entry per parameter (infinities allowed).
LevenbergMarquardtOutcome levenberg_marquardt(Evaluator& evaluator, const Eigen::VectorXd& start,
                                              const Eigen::VectorXd& lower,
                                              const Eigen::VectorXd& upper,
                                              const LevenbergMarquardtSettings& settings);

}  // namespace si::fit
