#include "core/chebyshev.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace si {
namespace {

// Coefficients c_k of sum c_k T_k(t) through the values at t_j = cos(pi j / n): the DCT-I with
// halved end terms (direct O(n^2) sum: n is small).
Eigen::VectorXd chebyshev_coefficients(const Eigen::VectorXd& v) {
  const int n = static_cast<int>(v.size()) - 1;
  Eigen::VectorXd c(n + 1);
  for (int k = 0; k <= n; ++k) {
    double s = 0;
    for (int j = 0; j <= n; ++j) {
      const double w = (j == 0 || j == n) ? 0.5 : 1.0;
      s += w * v[j] * std::cos(kPi * k * j / n);
    }
    c[k] = 2.0 * s / n;
  }
  c[0] /= 2;
  c[n] /= 2;
  return c;
}

// Coefficients of the derivative of sum c_k T_k(t): c'_{k-1} = c'_{k+1} + 2 k c_k, c'_0 halved.
Eigen::VectorXd derivative_coefficients(const Eigen::VectorXd& c) {
  const Eigen::Index n = c.size() - 1;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(n + 2);
  for (Eigen::Index k = n; k >= 1; --k) d[k - 1] = d[k + 1] + 2.0 * k * c[k];
  d[0] /= 2;
  return d.head(std::max<Eigen::Index>(n, 1));
}

double clenshaw(const Eigen::VectorXd& c, double t) {
  double b1 = 0, b2 = 0;
  for (Eigen::Index k = c.size() - 1; k >= 1; --k) {
    const double b0 = 2 * t * b1 - b2 + c[k];
    b2 = b1;
    b1 = b0;
  }
  return t * b1 - b2 + c[0];
}

double to_unit(double x, double a, double b) {
  return (2 * x - a - b) / (b - a);
}

}  // namespace

std::vector<double> chebyshev_points(double a, double b, int n) {
  SI_REQUIRE(n >= 1 && b > a, "chebyshev_points: need n >= 1 and a < b");
  std::vector<double> x(n + 1);
  for (int j = 0; j <= n; ++j) x[j] = (a + b) / 2 + (b - a) / 2 * std::cos(kPi * j / n);
  x[0] = b, x[n] = a;
  return x;
}

ChebyshevSeries::ChebyshevSeries(double a, double b, const std::vector<double>& values)
    : a_(a), b_(b) {
  SI_REQUIRE(values.size() >= 2 && b > a, "ChebyshevSeries: need two values and a < b");
  c_ = chebyshev_coefficients(Eigen::Map<const Eigen::VectorXd>(values.data(), values.size()));
  dc_ = derivative_coefficients(c_);
}

ChebyshevSeries ChebyshevSeries::from_coefficients(double a, double b, const Eigen::VectorXd& c) {
  SI_REQUIRE(c.size() >= 1 && b > a, "ChebyshevSeries: need a coefficient and a < b");
  ChebyshevSeries s;
  s.a_ = a, s.b_ = b, s.c_ = c;
  s.dc_ = derivative_coefficients(c);
  return s;
}

double ChebyshevSeries::operator()(double x) const {
  return clenshaw(c_, to_unit(x, a_, b_));
}

double ChebyshevSeries::derivative(double x) const {
  return clenshaw(dc_, to_unit(x, a_, b_)) * 2 / (b_ - a_);
}

ChebyshevTable2::ChebyshevTable2(double ax, double bx, double ay, double by,
                                 const Eigen::MatrixXd& values)
    : ax_(ax), bx_(bx), ay_(ay), by_(by) {
  SI_REQUIRE(values.rows() >= 2 && values.cols() >= 2 && bx > ax && by > ay,
             "ChebyshevTable2: need 2 x 2 values and non-empty intervals");
  Eigen::MatrixXd rows(values.rows(), values.cols());
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    rows.row(i) = chebyshev_coefficients(values.row(i).transpose()).transpose();
  c_.resize(values.rows(), values.cols());
  for (Eigen::Index j = 0; j < values.cols(); ++j) c_.col(j) = chebyshev_coefficients(rows.col(j));
  cx_ = Eigen::MatrixXd::Zero(c_.rows(), c_.cols());
  cy_ = Eigen::MatrixXd::Zero(c_.rows(), c_.cols());
  for (Eigen::Index j = 0; j < c_.cols(); ++j) {
    const Eigen::VectorXd d = derivative_coefficients(c_.col(j));
    cx_.col(j).head(d.size()) = d;
  }
  for (Eigen::Index i = 0; i < c_.rows(); ++i) {
    const Eigen::VectorXd d = derivative_coefficients(c_.row(i).transpose());
    cy_.row(i).head(d.size()) = d.transpose();
  }
}

namespace {

double clenshaw2(const Eigen::MatrixXd& c, double tx, double ty) {
  Eigen::VectorXd along_x(c.rows());
  for (Eigen::Index i = 0; i < c.rows(); ++i) along_x[i] = clenshaw(c.row(i).transpose(), ty);
  return clenshaw(along_x, tx);
}

}  // namespace

double ChebyshevTable2::operator()(double x, double y) const {
  return clenshaw2(c_, to_unit(x, ax_, bx_), to_unit(y, ay_, by_));
}

namespace {

// sum_i c(i, j) T_i(tx) per j: the coefficients of the series in y at x.
Eigen::VectorXd collapse_x(const Eigen::MatrixXd& c, double tx) {
  Eigen::VectorXd out(c.cols());
  for (Eigen::Index j = 0; j < c.cols(); ++j) out[j] = clenshaw(c.col(j), tx);
  return out;
}

}  // namespace

ChebyshevSeries ChebyshevTable2::slice(double x) const {
  return ChebyshevSeries::from_coefficients(ay_, by_, collapse_x(c_, to_unit(x, ax_, bx_)));
}

ChebyshevSeries ChebyshevTable2::slice_derivative_x(double x, double scale) const {
  return ChebyshevSeries::from_coefficients(
      ay_, by_, collapse_x(cx_, to_unit(x, ax_, bx_)) * (scale * 2 / (bx_ - ax_)));
}

double ChebyshevTable2::derivative_x(double x, double y) const {
  return clenshaw2(cx_, to_unit(x, ax_, bx_), to_unit(y, ay_, by_)) * 2 / (bx_ - ax_);
}

double ChebyshevTable2::derivative_y(double x, double y) const {
  return clenshaw2(cy_, to_unit(x, ax_, bx_), to_unit(y, ay_, by_)) * 2 / (by_ - ay_);
}

}  // namespace si
