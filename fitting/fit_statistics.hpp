// Parameter uncertainties and goodness of fit from the Jacobian and residuals at the solution:
// the one code path behind linear and nonlinear fits.
//
// Covariance C = s^2 (J^T J)^-1 with s^2 = SSE / (n - p) (Bates & Watts 1988, eq. 2.12), computed
// from a column-pivoted QR of J with its columns scaled to unit norm (so that parameters of
// very different magnitude, e.g. Pontius' x^2 ~ 1e13, do not spoil the rank decision); the
// 100(1 - alpha) % intervals are c_j -+ t(1 - alpha/2, n - p) sqrt(C_jj) (eq. 2.15).
#pragma once

#include <Eigen/Dense>

#include "fitting/fit_result.hpp"

namespace si::fit {

// Fills num_points, dof, interpolation, rank_deficient, covariance, std_errors, ci_lower/upper,
// sse, rmse, residual_std_dev, residuals, and (when `observed` is not empty) fitted, r_squared
// and pearson_r. `result.parameters` must be set; `result.confidence` is used.
void fill_statistics(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals,
                     const Eigen::VectorXd& observed, FitResult& result);

// False if a column of J is zero or not finite, or the columns are linearly dependent (rank
// decided on J with unit-norm columns, relative threshold 1e3 eps): some parameter is then not
// determined by the data.
bool has_full_column_rank(const Eigen::MatrixXd& jacobian);

}  // namespace si::fit
