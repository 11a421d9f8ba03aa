// Linear least squares y ~ X c solved directly by QR (no optimizer), with the statistics of
// fit_statistics.hpp (for a linear model the Jacobian is X). Polynomials and the power law in
// log space are linear in their parameters and are fitted here.
//
// The QR is column-pivoted and acts on X with its columns scaled to unit norm, which keeps
// monomial bases of wide range usable (NIST's Pontius: x up to 3e6, x^2 up to 9e12).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "fitting/fit_result.hpp"

namespace si::fit {

// Throws std::invalid_argument if sizes disagree or there are more parameters than points.
// `leverage`, if given, receives the diagonal of the hat matrix H = X (X^T X)^-1 X^T.
FitResult fit_linear(const Eigen::MatrixXd& design, const Eigen::VectorXd& y,
                     std::vector<std::string> names, double confidence = 0.95,
                     Eigen::VectorXd* leverage = nullptr);

// y = a0 + a1 x + ... + aN x^N, parameters named a0..aN. Needs at least N + 1 points; with
// exactly N + 1 the result is flagged as interpolation (no degrees of freedom left).
FitResult fit_polynomial(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree,
                         double confidence = 0.95, Eigen::VectorXd* leverage = nullptr);

// y = C1 x^C2 fitted in log space: ln y = ln C1 + C2 ln x by linear least squares. Needs
// x > 0 and y > 0. Residuals, SSE, RMSE and R^2 are those of ln y. C1's standard error is the
// delta-method C1 se(ln C1), its interval exp of the interval of ln C1 (exact, not symmetric).
FitResult fit_power_law_log(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                            double confidence = 0.95);

}  // namespace si::fit
