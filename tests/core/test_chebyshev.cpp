// Chebyshev interpolation (core/chebyshev.hpp) on smooth functions with known derivatives: the
// error of a degree-n interpolant of an analytic function falls geometrically (Trefethen 2013,
// ch. 8), so degree 30 reproduces these to near roundoff.
#include <gtest/gtest.h>

#include <cmath>

#include "core/chebyshev.hpp"

namespace si {
namespace {

double f(double x) {
  return std::exp(x) * std::sin(3 * x);
}
double df(double x) {
  return std::exp(x) * (std::sin(3 * x) + 3 * std::cos(3 * x));
}

TEST(ChebyshevSeries, AnalyticFunction_ValueAndDerivativeToNearRoundoff) {
  const std::vector<double> x = chebyshev_points(0.5, 2.5, 30);
  std::vector<double> v;
  for (double xi : x) v.push_back(f(xi));
  const ChebyshevSeries s(0.5, 2.5, v);
  for (std::size_t j = 0; j < x.size(); ++j) EXPECT_NEAR(s(x[j]), v[j], 1e-13);  // the nodes
  for (double t = 0.5; t <= 2.5; t += 0.0731) {
    EXPECT_NEAR(s(t), f(t), 1e-12);
    EXPECT_NEAR(s.derivative(t), df(t), 1e-10);
  }
}

TEST(ChebyshevSeries, LinearFunction_IsExactAtDegreeOne) {
  const ChebyshevSeries s(-1, 3, {7.0, -1.0});  // at x = 3 and x = -1: f = 2 x + 1
  EXPECT_NEAR(s(0.25), 1.5, 1e-15);
  EXPECT_NEAR(s.derivative(2.0), 2.0, 1e-15);
}

TEST(ChebyshevTable2, AnalyticFunctionOfTwoVariables) {
  const auto g = [](double x, double y) { return std::exp(x * y) * std::cos(x - 2 * y); };
  const std::vector<double> x = chebyshev_points(0, 2, 24), y = chebyshev_points(-1, 1, 20);
  Eigen::MatrixXd v(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < y.size(); ++j) v(i, j) = g(x[i], y[j]);
  const ChebyshevTable2 t(0, 2, -1, 1, v);
  const auto gx = [](double p, double q) {
    return std::exp(p * q) * (q * std::cos(p - 2 * q) - std::sin(p - 2 * q));
  };
  const auto gy = [](double p, double q) {
    return std::exp(p * q) * (p * std::cos(p - 2 * q) + 2 * std::sin(p - 2 * q));
  };
  for (double a = 0; a <= 2; a += 0.137)
    for (double b = -1; b <= 1; b += 0.173) {
      EXPECT_NEAR(t(a, b), g(a, b), 1e-11);
      EXPECT_NEAR(t.derivative_x(a, b), gx(a, b), 1e-9);
      EXPECT_NEAR(t.derivative_y(a, b), gy(a, b), 1e-9);
    }
}

}  // namespace
}  // namespace si
