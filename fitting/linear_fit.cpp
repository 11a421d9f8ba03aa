#include "fitting/linear_fit.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "fitting/fit_statistics.hpp"

namespace si::fit {

FitResult fit_linear(const Eigen::MatrixXd& design, const Eigen::VectorXd& y,
                     std::vector<std::string> names, double confidence, Eigen::VectorXd* leverage) {
  const Eigen::Index m = design.rows();
  const Eigen::Index p = design.cols();
  if (y.size() != m || static_cast<Eigen::Index>(names.size()) != p)
    throw std::invalid_argument("linear fit: sizes of design matrix, data and names disagree");
  if (p < 1) throw std::invalid_argument("linear fit: no parameters");
  if (m < p)
    throw std::invalid_argument("linear fit: " + std::to_string(p) + " parameters need at least " +
                                std::to_string(p) + " points, got " + std::to_string(m));
  if (!design.allFinite() || !y.allFinite())
    throw std::invalid_argument("linear fit: data contain non-finite values");

  Eigen::VectorXd norms = design.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < p; ++j)
    if (norms[j] == 0.0) norms[j] = 1.0;
  const Eigen::MatrixXd scaled = design * norms.cwiseInverse().asDiagonal();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(scaled);
  FitResult res;
  res.names = std::move(names);
  res.confidence = confidence;
  res.method = "linear least squares (column-pivoted QR)";
  res.parameters = qr.solve(y).cwiseQuotient(norms);
  fill_statistics(design, design * res.parameters - y, y, res);
  res.at_bound.assign(p, false);
  res.status = res.rank_deficient ? FitStatus::kFailed : FitStatus::kConverged;
  res.reason = res.rank_deficient ? "design matrix is rank-deficient: parameters not determined"
                                  : "direct solution of the linear problem";
  if (leverage != nullptr) {
    // h_ii = |row i of Q1|^2, Q1 the first p columns of Q (the hat matrix is Q1 Q1^T).
    const Eigen::MatrixXd q1 = qr.householderQ() * Eigen::MatrixXd::Identity(m, p);
    *leverage = q1.rowwise().squaredNorm();
  }
  return res;
}

FitResult fit_polynomial(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree,
                         double confidence, Eigen::VectorXd* leverage) {
  if (degree < 0) throw std::invalid_argument("polynomial degree must be >= 0");
  if (x.size() != y.size()) throw std::invalid_argument("x and y differ in length");
  if (x.size() < degree + 1)
    throw std::invalid_argument("a polynomial of degree " + std::to_string(degree) + " has " +
                                std::to_string(degree + 1) + " coefficients and needs at least " +
                                std::to_string(degree + 1) + " points, got " +
                                std::to_string(x.size()));
  Eigen::MatrixXd design(x.size(), degree + 1);
  std::vector<std::string> names;
  for (int k = 0; k <= degree; ++k) {
    design.col(k) = x.array().pow(k);
    names.push_back("a" + std::to_string(k));
  }
  FitResult res = fit_linear(design, y, std::move(names), confidence, leverage);
  if (res.interpolation)
    res.reason += "; interpolation: " + std::to_string(degree + 1) + " coefficients through " +
                  std::to_string(x.size()) + " points, no residual degrees of freedom";
  return res;
}

FitResult fit_power_law_log(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double confidence) {
  if (x.size() != y.size()) throw std::invalid_argument("x and y differ in length");
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!(x[i] > 0.0) || !(y[i] > 0.0))
      throw std::invalid_argument("power law in log space needs x > 0 and y > 0 (point " +
                                  std::to_string(i + 1) + ": x = " + std::to_string(x[i]) +
                                  ", y = " + std::to_string(y[i]) + ")");
  Eigen::MatrixXd design(x.size(), 2);
  design.col(0).setOnes();
  design.col(1) = x.array().log();
  FitResult res = fit_linear(design, y.array().log().matrix(), {"C1", "C2"}, confidence);
  // Back to C1 = exp(ln C1); the covariance by the delta method, G = diag(C1, 1).
  const double c1 = std::exp(res.parameters[0]);
  res.parameters[0] = c1;
  res.std_errors[0] *= c1;
  res.ci_lower[0] = std::exp(res.ci_lower[0]);
  res.ci_upper[0] = std::exp(res.ci_upper[0]);
  res.covariance.row(0) *= c1;
  res.covariance.col(0) *= c1;
  res.method = "linear least squares of ln y on ln x (QR); residuals, RMSE and R^2 in log space";
  return res;
}

}  // namespace si::fit
