#include "fitting/fit_statistics.hpp"

#include <cmath>
#include <limits>

#include "fitting/student_t.hpp"

namespace si::fit {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Column-pivoted QR of J D^-1, D = the column norms (returned in `norms`); false if a column is
// zero or not finite.
bool scaled_qr(const Eigen::MatrixXd& jac, Eigen::VectorXd& norms,
               Eigen::ColPivHouseholderQR<Eigen::MatrixXd>& qr) {
  norms = jac.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < norms.size(); ++j)
    if (!(norms[j] > 0.0) || !std::isfinite(norms[j])) return false;
  qr.compute(jac * norms.cwiseInverse().asDiagonal());
  // Rank threshold: 1e3 eps relative to the largest pivot (Eigen's default is looser).
  qr.setThreshold(1e3 * std::numeric_limits<double>::epsilon());
  return true;
}

// (J^T J)^-1 from J D^-1 P = Q R: (J^T J)^-1 = D^-1 P R^-1 R^-T P^T D^-1. False if J is
// rank-deficient.
bool inverse_normal_matrix(const Eigen::MatrixXd& jac, Eigen::MatrixXd& inverse) {
  const Eigen::Index n = jac.cols();
  Eigen::VectorXd norms;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  if (!scaled_qr(jac, norms, qr) || qr.rank() < n) return false;
  const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(n, n).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd r_inv =
      r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(n, n));
  const Eigen::MatrixXd perm = qr.colsPermutation();
  const Eigen::MatrixXd pr = perm * r_inv;
  inverse =
      norms.cwiseInverse().asDiagonal() * (pr * pr.transpose()) * norms.cwiseInverse().asDiagonal();
  return true;
}

double pearson(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::ArrayXd da = a.array() - a.mean();
  const Eigen::ArrayXd db = b.array() - b.mean();
  const double denom = std::sqrt((da * da).sum() * (db * db).sum());
  return denom > 0.0 ? (da * db).sum() / denom : kNaN;
}

}  // namespace

bool has_full_column_rank(const Eigen::MatrixXd& jac) {
  Eigen::VectorXd norms;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  return scaled_qr(jac, norms, qr) && qr.rank() == jac.cols();
}

void fill_statistics(const Eigen::MatrixXd& jac, const Eigen::VectorXd& r,
                     const Eigen::VectorXd& observed, FitResult& out) {
  const int n = static_cast<int>(r.size());
  const int p = static_cast<int>(out.parameters.size());
  out.num_points = n;
  out.dof = n - p;
  out.interpolation = p >= n;
  out.residuals = r;
  out.sse = r.squaredNorm();
  out.rmse = std::sqrt(out.sse / n);
  out.residual_std_dev = out.dof > 0 ? std::sqrt(out.sse / out.dof) : kNaN;

  Eigen::MatrixXd inverse;
  out.rank_deficient = !inverse_normal_matrix(jac, inverse);
  out.covariance = Eigen::MatrixXd::Constant(p, p, kNaN);
  out.std_errors = Eigen::VectorXd::Constant(p, kNaN);
  out.ci_lower = Eigen::VectorXd::Constant(p, kNaN);
  out.ci_upper = Eigen::VectorXd::Constant(p, kNaN);
  if (!out.rank_deficient && out.dof > 0) {
    const double s2 = out.sse / out.dof;
    out.covariance = s2 * inverse;
    out.std_errors = out.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
    const double t = student_t_quantile(0.5 + 0.5 * out.confidence, out.dof);
    out.ci_lower = out.parameters - t * out.std_errors;
    out.ci_upper = out.parameters + t * out.std_errors;
  }

  out.fitted.resize(0);
  out.r_squared = kNaN;
  out.pearson_r = kNaN;
  if (observed.size() == n) {
    out.fitted = observed + r;
    const double sst = (observed.array() - observed.mean()).square().sum();
    out.r_squared = sst > 0.0 ? 1.0 - out.sse / sst : kNaN;
    out.pearson_r = pearson(out.fitted, observed);
  }
}

}  // namespace si::fit
