#include "fitting/confidence_region.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "fitting/fisher_f.hpp"

namespace si::fit {

double ConfidenceEllipsoid::distance(const Eigen::VectorXd& center,
                                     const Eigen::VectorXd& c) const {
  const Eigen::VectorXd d = c - center;
  return d.dot(shape.ldlt().solve(d));
}

ConfidenceEllipsoid confidence_ellipsoid(const Eigen::MatrixXd& covariance, int dof,
                                         double confidence) {
  if (!covariance.allFinite() || covariance.rows() != covariance.cols() || covariance.rows() < 1)
    throw std::invalid_argument(
        "confidence ellipsoid: the covariance is not a finite square matrix");
  if (dof < 1) throw std::invalid_argument("confidence ellipsoid: needs dof >= 1");
  const auto p = static_cast<double>(covariance.rows());
  ConfidenceEllipsoid e;
  e.confidence = confidence;
  e.f_quantile = fisher_f_quantile(confidence, p, dof);
  e.shape = p * e.f_quantile * covariance;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 *
                                                           (covariance + covariance.transpose()));
  // Eigen returns ascending eigenvalues: reverse to put the longest axis first.
  e.half_lengths = (p * e.f_quantile * eig.eigenvalues().reverse().cwiseMax(0.0)).cwiseSqrt();
  e.axes = eig.eigenvectors().rowwise().reverse();
  e.shadow_half_widths = (p * e.f_quantile * covariance.diagonal().cwiseMax(0.0)).cwiseSqrt();
  return e;
}

Eigen::MatrixXd correlation_matrix(const Eigen::MatrixXd& covariance) {
  const Eigen::VectorXd sd = covariance.diagonal().cwiseSqrt();
  Eigen::MatrixXd r(covariance.rows(), covariance.cols());
  for (Eigen::Index i = 0; i < r.rows(); ++i)
    for (Eigen::Index j = 0; j < r.cols(); ++j)
      r(i, j) = sd[i] > 0.0 && sd[j] > 0.0 ? covariance(i, j) / (sd[i] * sd[j])
                                           : std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace si::fit
