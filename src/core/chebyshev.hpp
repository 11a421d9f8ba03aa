// Chebyshev interpolation of smooth functions on an interval and on a rectangle (Trefethen,
// Approximation Theory and Approximation Practice, 2013, ch. 2-3): values at the Chebyshev-Lobatto
// points x_j = m + d cos(pi j / n), j = 0..n (m, d the interval's midpoint and half-width),
// coefficients by the discrete cosine transform, evaluation and derivative by Clenshaw's
// recurrence. For the tabulated local contact laws (contact/layer_contact_law.hpp).
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace si {

// The n + 1 Chebyshev-Lobatto points of [a, b], from b down to a.
std::vector<double> chebyshev_points(double a, double b, int n);

class ChebyshevSeries {
 public:
  ChebyshevSeries() = default;
  // values[j] at chebyshev_points(a, b, n)[j], n = values.size() - 1 >= 1.
  ChebyshevSeries(double a, double b, const std::vector<double>& values);
  // From the coefficients of T_k((2x - a - b)/(b - a)) instead of values.
  static ChebyshevSeries from_coefficients(double a, double b, const Eigen::VectorXd& c);
  double operator()(double x) const;
  double derivative(double x) const;
  double lower() const { return a_; }
  double upper() const { return b_; }

 private:
  double a_ = 0, b_ = 1;
  Eigen::VectorXd c_;   // coefficients of T_k
  Eigen::VectorXd dc_;  // of the derivative, d/dt in t = (x - m) / d
};

// f(x, y) on [ax, bx] x [ay, by] from values(i, j) at (chebyshev_points(ax, bx, nx)[i],
// chebyshev_points(ay, by, ny)[j]).
class ChebyshevTable2 {
 public:
  ChebyshevTable2() = default;
  ChebyshevTable2(double ax, double bx, double ay, double by, const Eigen::MatrixXd& values);
  double operator()(double x, double y) const;
  double derivative_x(double x, double y) const;
  double derivative_y(double x, double y) const;
  // f(x, .) and scale df/dx(x, .) as series in y: the work in x done once for many y.
  ChebyshevSeries slice(double x) const;
  ChebyshevSeries slice_derivative_x(double x, double scale = 1.0) const;

 private:
  double ax_ = 0, bx_ = 1, ay_ = 0, by_ = 1;
  Eigen::MatrixXd c_, cx_, cy_;  // coefficients of T_i(x) T_j(y) of f, df/dx, df/dy (unit box)
};

}  // namespace si
