// Small algebraic continuation problems with known answers, shared by the continuation tests.
// Each has a dense analytic Jacobian factored by Eigen's partial-pivot LU.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "continuation/problem.hpp"

namespace si::cont::test {

using Matrix = Eigen::MatrixXd;

// Implements factorize/solve/jacobian_sign from an analytic dense Jacobian.
class DenseProblem : public Problem {
 public:
  virtual Matrix jacobian(const Vector& x, double p) const = 0;

  bool factorize(const Vector& x, double p) override {
    const Matrix J = jacobian(x, p);
    lu_.compute(J);
    const double det = lu_.determinant();
    sign_ = det > 0 ? 1 : (det < 0 ? -1 : 0);
    ++factorizations_;
    return std::isfinite(det) && det != 0.0;
  }
  bool solve(Vector& b) override {
    b = lu_.solve(b);
    return b.allFinite();
  }
  int jacobian_sign() override { return sign_; }
  int factorizations() const { return factorizations_; }

 private:
  Eigen::PartialPivLU<Matrix> lu_;
  int sign_ = 0;
  int factorizations_ = 0;
};

// x^2 + p^2 = 1: a closed branch with limit points at p = +-1 (x = 0).
class CircleProblem final : public DenseProblem {
 public:
  int size() const override { return 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F.resize(1);
    F(0) = x(0) * x(0) + p * p - 1.0;
    return true;
  }
  Matrix jacobian(const Vector& x, double /*p*/) const override {
    return Matrix::Constant(1, 1, 2.0 * x(0));
  }
  bool residual_p(const Vector& /*x*/, double p, Vector& out) override {
    out = Vector::Constant(1, 2.0 * p);
    return true;
  }
  std::vector<std::string> monitor_names() const override { return {"x"}; }
  Vector monitors(const Vector& x, double /*p*/) override { return x; }
};

// sinh(x) = sinh(p^3 - 3p): the branch is y = x = p^3 - 3p, with extrema of y at p = -1 (max)
// and p = +1 (min), zero crossings at p = 0, +-sqrt(3) and the inflection of y against p at p = 0
// (y'' = 6p). Nonlinear in x, so Newton needs several iterations. The signature is the sign of
// y, which changes at the zero crossings.
class CubicBranchProblem final : public DenseProblem {
 public:
  static double branch(double p) { return p * p * p - 3.0 * p; }
  int size() const override { return 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F = Vector::Constant(1, std::sinh(x(0)) - std::sinh(branch(p)));
    return true;
  }
  Matrix jacobian(const Vector& x, double /*p*/) const override {
    return Matrix::Constant(1, 1, std::cosh(x(0)));
  }
  std::vector<std::string> monitor_names() const override { return {"y", "p"}; }
  Vector monitors(const Vector& x, double p) override { return Vector{{x(0), p}}; }
  std::vector<int> signature(const Vector& x, double /*p*/) override { return {x(0) > 0 ? 1 : 0}; }
};

// F_i(x, p) = x_i^3 + sin(p x_i) + x_{i+1} - p^2 (i + 1), x_n := 0: a small coupled nonlinear
// system with an analytic dF/dp (for the finite-difference check and the Newton tests).
class CoupledProblem final : public DenseProblem {
 public:
  explicit CoupledProblem(int n) : n_(n) {}
  int size() const override { return n_; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F.resize(n_);
    for (int i = 0; i < n_; ++i)
      F(i) =
          std::pow(x(i), 3) + std::sin(p * x(i)) + (i + 1 < n_ ? x(i + 1) : 0.0) - p * p * (i + 1);
    return true;
  }
  Matrix jacobian(const Vector& x, double p) const override {
    Matrix J = Matrix::Zero(n_, n_);
    for (int i = 0; i < n_; ++i) {
      J(i, i) = 3.0 * x(i) * x(i) + p * std::cos(p * x(i));
      if (i + 1 < n_) J(i, i + 1) = 1.0;
    }
    return J;
  }
  bool residual_p(const Vector& x, double p, Vector& out) override {
    out.resize(n_);
    for (int i = 0; i < n_; ++i) out(i) = x(i) * std::cos(p * x(i)) - 2.0 * p * (i + 1);
    return true;
  }

 private:
  int n_;
};

}  // namespace si::cont::test
