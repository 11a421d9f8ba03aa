// The linear-approximation inference of a least-squares estimate c^ with covariance
// C = s^2 (J^T W J)^-1 (fit_statistics.hpp computes C, the standard errors and the t intervals):
// the joint confidence region, an ellipsoid, and the correlation matrix.
//
// Joint 100(1 - alpha) % region (Bates & Watts 1988, sec. 2.3; Seber & Wild 1989, sec. 5.2):
//   { c : (c - c^)^T C^-1 (c - c^) <= p F(1 - alpha; p, n - p) },
// an ellipsoid with the eigenvectors of C as axes and half-lengths sqrt(p F lambda_k(C)). It is
// exact for a model linear in c with Gaussian errors and approximate otherwise (the curvature
// of the expectation surface is neglected; Bates & Watts ch. 7 measure it). The marginal
// intervals c_j -+ t(1 - alpha/2, n - p) sqrt(C_jj) are narrower than the ellipsoid's shadow on
// each axis, which is sqrt(p F C_jj): they answer a question about one parameter at a time.
#pragma once

#include <Eigen/Dense>

namespace si::fit {

struct ConfidenceEllipsoid {
  double confidence = 0.95;
  double f_quantile = 0;               // F(confidence; p, dof)
  Eigen::MatrixXd shape;               // p F C: the region is (c - c^)^T shape^-1 (c - c^) <= 1
  Eigen::VectorXd half_lengths;        // sqrt(p F lambda_k(C)), descending
  Eigen::MatrixXd axes;                // unit eigenvectors of C, one column per half-length
  Eigen::VectorXd shadow_half_widths;  // sqrt(p F C_jj): the region's extent along each c_j

  // (c - center)^T shape^-1 (c - center): <= 1 inside the region.
  double distance(const Eigen::VectorXd& center, const Eigen::VectorXd& c) const;
};

// From the covariance C (p x p, symmetric positive definite) and the residual degrees of freedom.
// Throws std::invalid_argument if C is not finite or dof < 1.
ConfidenceEllipsoid confidence_ellipsoid(const Eigen::MatrixXd& covariance, int dof,
                                         double confidence);

// C_ij / sqrt(C_ii C_jj); NaN entries where C is not finite.
Eigen::MatrixXd correlation_matrix(const Eigen::MatrixXd& covariance);

}  // namespace si::fit
