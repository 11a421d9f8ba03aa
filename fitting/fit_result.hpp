// What a fit returns: status and reason, the parameters with standard errors and confidence
// intervals, goodness-of-fit statistics, residuals and evaluation counts. Linear fits (QR) and
// nonlinear fits (NLopt + Levenberg-Marquardt) fill the same struct through the same statistics
// code (fit_statistics.hpp).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "fitting/least_squares_problem.hpp"

namespace si::fit {

enum class FitStatus {
  kConverged,  // a minimum of S to the tolerances (or the exact linear solution)
  kStalled,    // stopped by the evaluation/iteration budget before meeting the tolerances
  kFailed,     // no finite point better than the start was found
};

const char* to_string(FitStatus status);

struct FitResult {
  FitStatus status = FitStatus::kFailed;
  std::string reason;  // why it stopped, in words
  std::string method;  // what solved it, e.g. "NLopt LD_LBFGS + Levenberg-Marquardt polish"

  std::vector<std::string> names;
  Eigen::VectorXd parameters;
  // Standard errors sqrt(diag(s^2 (J^T J)^-1)), s^2 = SSE / dof, from the Jacobian at the
  // solution (Bates & Watts 1988, sec. 2.3); NaN when dof = 0 or J is rank-deficient.
  Eigen::VectorXd std_errors;
  Eigen::VectorXd ci_lower, ci_upper;  // parameter -+ t(1 - alpha/2, dof) * standard error
  Eigen::MatrixXd covariance;
  double confidence = 0.95;

  int num_points = 0;
  int dof = 0;                  // num_points - number of parameters
  bool interpolation = false;   // number of parameters >= number of points: nothing left over
  bool rank_deficient = false;  // J^T J singular at the solution: some parameters not determined
  std::vector<bool> at_bound;   // parameter sits on a bound: its interval is not meaningful

  double sse = 0;               // sum of squared residuals
  double rmse = 0;              // sqrt(SSE / n)
  double residual_std_dev = 0;  // s = sqrt(SSE / dof), NIST's "residual standard deviation"
  double r_squared = 0;         // 1 - SSE / sum (y - mean y)^2 (needs observations; else NaN)
  double pearson_r = 0;         // correlation of fitted and observed values (else NaN)
  Eigen::VectorXd residuals;    // r = fitted - observed for curve fits
  Eigen::VectorXd fitted;       // observed + residuals (empty without observations)

  EvaluationCounts evaluations;
  // The NLopt stage (nonlinear fits; linear fits leave these empty): the algorithm whose result
  // was kept, its return code (nlopt.h; negative = failure), whether it was the derivative-free
  // fallback after the gradient method failed, and its best point before any polish, so that
  // what NLopt found can be judged on its own.
  std::string nlopt_algorithm;
  int nlopt_code = 0;  // 0: NLopt not used
  bool nlopt_fallback = false;
  Eigen::VectorXd nlopt_parameters;
  double nlopt_sse = 0;
};

}  // namespace si::fit
