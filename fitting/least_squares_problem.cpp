#include "fitting/least_squares_problem.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace si::fit {

void validate(const LeastSquaresProblem& p) {
  if (p.num_parameters() < 1) throw std::invalid_argument("a fit needs at least one parameter");
  if (p.num_residuals < 1) throw std::invalid_argument("a fit needs at least one data point");
  if (!p.residuals) throw std::invalid_argument("the problem has no residual function");
  if (p.observed.size() != 0 && p.observed.size() != p.num_residuals)
    throw std::invalid_argument("observed values: " + std::to_string(p.observed.size()) +
                                " given for " + std::to_string(p.num_residuals) + " residuals");
}

Evaluator::Evaluator(const LeastSquaresProblem& problem, Eigen::VectorXd scale)
    : problem_(problem), scale_(std::move(scale)) {
  validate(problem_);
  if (scale_.size() != problem_.num_parameters())
    throw std::invalid_argument("parameter scale has the wrong size");
}

Eigen::VectorXd Evaluator::residuals(const Eigen::VectorXd& c) {
  Eigen::VectorXd r(problem_.num_residuals);
  problem_.residuals(c, r);
  ++counts_.residuals;
  return r;
}

double Evaluator::sum_of_squares(const Eigen::VectorXd& r) const {
  const double s = r.squaredNorm();
  return std::isfinite(s) ? s : std::numeric_limits<double>::infinity();
}

Eigen::MatrixXd Evaluator::jacobian(const Eigen::VectorXd& c) {
  const int n = problem_.num_parameters();
  Eigen::MatrixXd jac(problem_.num_residuals, n);
  ++counts_.jacobians;
  if (problem_.jacobian) {
    problem_.jacobian(c, jac);
    return jac;
  }
  counts_.finite_differences = true;
  const double h0 = std::cbrt(std::numeric_limits<double>::epsilon());
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd cp = c;
    Eigen::VectorXd cm = c;
    const double h = h0 * std::max(std::abs(c[j]), std::abs(scale_[j]));
    cp[j] += h;
    cm[j] -= h;
    // The step actually taken, (c + h) - (c - h), not 2h: removes the representation error.
    jac.col(j) = (residuals(cp) - residuals(cm)) / (cp[j] - cm[j]);
  }
  return jac;
}

}  // namespace si::fit
