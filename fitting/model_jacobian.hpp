// The Jacobian of an expensive model y(c) (one value per data point) by finite differences, for
// parameters held within bounds: the sensitivities behind a calibration's covariance.
//
// Step of parameter j: h_j = relative_step * max(|c_j|, 0.01 (upper_j - lower_j)), at most a
// quarter of the bound width - relative to the parameter, and to its range where the parameter
// is near zero. Central differences (error O(h^2)) where c_j +- h_j both lie within the bounds,
// else one-sided into the box (error O(h)). The model's own noise (a continuation run converged
// to a tolerance, a path interpolated between adaptive points) sets the useful step: with noise
// eps_m relative, the central-difference error is ~eps_m / h + h^2, smallest near
// h ~ eps_m^(1/3); the default 1e-3 suits eps_m ~ 1e-9 (Gill, Murray & Wright 1981, sec. 8.6).
#pragma once

#include <Eigen/Dense>
#include <functional>

namespace si::fit {

// y(c), or false when the model cannot be evaluated at c. With concurrency > 1 it is called from
// several threads at once and must be thread-safe.
using ModelValues = std::function<bool(const Eigen::VectorXd& c, Eigen::VectorXd& y)>;

struct ModelJacobian {
  Eigen::MatrixXd jacobian;  // dy_i / dc_j; a column is NaN where the model failed
  Eigen::VectorXd steps;     // h_j actually used (negative: a backward difference)
  Eigen::VectorXi central;   // 1 where the difference was central
  int evaluations = 0;       // model calls (a failed one included)
  bool ok = true;            // every column computed
};

enum class DifferenceScheme {
  kCentral,  // 2p evaluations, error O(h^2); one-sided at a bound
  kForward,  // p evaluations, error O(h); backward at the upper bound
};

// y0 = y(c) (already known, used by one-sided differences). lower/upper: one per parameter,
// finite. All the points are known before any is evaluated, so they are evaluated `concurrency`
// at a time (a central difference whose one point fails falls back to the one-sided difference
// with the other: no further evaluation).
ModelJacobian model_jacobian(const ModelValues& model, const Eigen::VectorXd& c,
                             const Eigen::VectorXd& y0, const Eigen::VectorXd& lower,
                             const Eigen::VectorXd& upper, double relative_step = 1e-3,
                             DifferenceScheme scheme = DifferenceScheme::kCentral,
                             int concurrency = 1);

}  // namespace si::fit
