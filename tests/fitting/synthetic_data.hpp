// Synthetic data for the fitting tests: points on a known curve, optionally with seeded Gaussian
// noise, so that recovered parameters and interval coverage can be checked against the truth.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <random>

namespace si::fit::testing {

inline Eigen::VectorXd grid(double a, double b, int n) {
  return Eigen::VectorXd::LinSpaced(n, a, b);
}

// y_i = f(x_i) + N(0, sigma^2) from a Mersenne twister seeded with `seed` (sigma = 0: exact).
inline Eigen::VectorXd sample(const Eigen::VectorXd& x, const std::function<double(double)>& f,
                              double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::VectorXd y(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) y[i] = f(x[i]) + sigma * noise(rng);
  return y;
}

// Max over j of |a_j - b_j| / |b_j|.
inline double max_relative_error(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return ((a - b).cwiseAbs().array() / b.cwiseAbs().array()).maxCoeff();
}

}  // namespace si::fit::testing
