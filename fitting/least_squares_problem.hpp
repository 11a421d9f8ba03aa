// A nonlinear least-squares problem: find the parameters c minimising S(c) = sum_i r_i(c)^2.
// The problem is given as functors (style.md, "Fitting"): the residuals r(c), required, and
// optionally the Jacobian J_ij = dr_i/dc_j; without one, central finite differences are used.
// For a curve fit r_i = f(x_i; c) - y_i, and the observations y may be attached so that the
// result also reports R^2 and Pearson's r of fitted against observed values.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace si::fit {

// r is already sized to num_residuals when called; non-finite values mark an invalid point.
using ResidualFunction = std::function<void(const Eigen::VectorXd& c, Eigen::VectorXd& r)>;
// jac is already sized num_residuals x num_parameters when called.
using JacobianFunction = std::function<void(const Eigen::VectorXd& c, Eigen::MatrixXd& jac)>;

struct LeastSquaresProblem {
  int num_residuals = 0;
  std::vector<std::string> parameter_names;  // one per parameter, in the order of c
  ResidualFunction residuals;                // required
  JacobianFunction jacobian;                 // optional: empty means finite differences
  Eigen::VectorXd observed;                  // optional: y of r = f - y (size num_residuals)

  int num_parameters() const { return static_cast<int>(parameter_names.size()); }
};

struct EvaluationCounts {
  int residuals = 0;  // calls of the residual functor (finite differences included)
  int jacobians = 0;  // Jacobians formed, analytic or by differences
  bool finite_differences = false;
};

// Evaluates a problem and counts the calls. The finite-difference step of parameter j is
// h_j = eps^(1/3) max(|c_j|, scale_j) (central differences, error O(h^2): Nocedal & Wright
// 2006, sec. 8.1), so that a parameter at zero still gets a step of its typical size.
class Evaluator {
 public:
  Evaluator(const LeastSquaresProblem& problem, Eigen::VectorXd scale);

  Eigen::VectorXd residuals(const Eigen::VectorXd& c);
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& c);
  // S(c) = |r(c)|^2, or +infinity where the residuals are not finite.
  double sum_of_squares(const Eigen::VectorXd& r) const;

  const LeastSquaresProblem& problem() const { return problem_; }
  const EvaluationCounts& counts() const { return counts_; }

 private:
  const LeastSquaresProblem& problem_;
  Eigen::VectorXd scale_;
  EvaluationCounts counts_;
};

// Throws std::invalid_argument unless the problem is complete and consistent.
void validate(const LeastSquaresProblem& problem);

}  // namespace si::fit
