// The 1-D Bratu problem u'' + lambda e^u = 0 on (0, 1), u(0) = u(1) = 0, by second-order
// central differences on n interior nodes (h = 1/(n+1)), parameter p = lambda. The tridiagonal
// Jacobian is factored by the Thomas algorithm without pivoting (J is indefinite past the fold,
// but its pivots stay nonzero away from it; a zero pivot reports failure). The sign of det J is
// the product of the pivots' signs.
// Inner product: the discrete L2 product h a.b, so that arclength does not grow with n.
#pragma once

#include <cmath>
#include <vector>

#include "continuation/problem.hpp"

namespace si::cont::test {

class BratuProblem final : public Problem {
 public:
  explicit BratuProblem(int n) : n_(n), h_(1.0 / (n + 1)) {}

  int size() const override { return n_; }

  bool residual(const Vector& u, double lambda, Vector& F) override {
    F.resize(n_);
    for (int i = 0; i < n_; ++i) {
      const double left = i > 0 ? u(i - 1) : 0.0;
      const double right = i + 1 < n_ ? u(i + 1) : 0.0;
      F(i) = (left - 2.0 * u(i) + right) / (h_ * h_) + lambda * std::exp(u(i));
    }
    return true;
  }

  bool residual_p(const Vector& u, double /*lambda*/, Vector& out) override {
    out = u.array().exp().matrix();
    return true;
  }

  // Thomas algorithm on J = tridiag(1/h^2, -2/h^2 + lambda e^u_i, 1/h^2).
  bool factorize(const Vector& u, double lambda) override {
    const double off = 1.0 / (h_ * h_);
    pivot_.assign(n_, 0.0);
    sign_ = 1;
    for (int i = 0; i < n_; ++i) {
      const double diag = -2.0 * off + lambda * std::exp(u(i));
      pivot_[i] = i == 0 ? diag : diag - off * off / pivot_[i - 1];
      if (pivot_[i] == 0.0 || !std::isfinite(pivot_[i])) return false;
      if (pivot_[i] < 0.0) sign_ = -sign_;
    }
    return true;
  }

  bool solve(Vector& b) override {
    ++solves_;
    const double off = 1.0 / (h_ * h_);
    for (int i = 1; i < n_; ++i) b(i) -= off / pivot_[i - 1] * b(i - 1);
    b(n_ - 1) /= pivot_[n_ - 1];
    for (int i = n_ - 2; i >= 0; --i) b(i) = (b(i) - off * b(i + 1)) / pivot_[i];
    return b.allFinite();
  }

  int jacobian_sign() override { return sign_; }
  int solves() const { return solves_; }  // linear solves with J so far

  double inner(const Vector& a, const Vector& b) const override { return h_ * a.dot(b); }

  std::vector<std::string> monitor_names() const override { return {"u_max"}; }
  Vector monitors(const Vector& u, double /*lambda*/) override {
    return Vector::Constant(1, u.maxCoeff());
  }

 private:
  int n_;
  double h_;
  std::vector<double> pivot_;
  int sign_ = 0;
  int solves_ = 0;
};

// The exact fold of the continuous problem. The solution is
// u = -2 ln[cosh((x - 1/2) theta/2) / cosh(theta/4)] with theta = sqrt(2 lambda) cosh(theta/4),
// so lambda = 8 y^2 / cosh^2(y), y = theta/4, whose maximum satisfies y tanh(y) = 1, giving
// lambda_c = 8 (y^2 - 1) (cosh^2 y = y^2 / (y^2 - 1) there). Published: lambda_c = 3.513830719
// (Boyd 1986, "An analytical and numerical study of the two-dimensional Bratu equation",
// J. Sci. Comput. 1; Mohsen 2014, "A simple solution of the Bratu problem", Comput. Math. Appl. 67,
// 26-33).
inline double bratu_critical_lambda() {
  double y = 1.2;
  for (int it = 0; it < 50; ++it) {  // Newton on y tanh y - 1 = 0
    const double t = std::tanh(y);
    y -= (y * t - 1.0) / (t + y * (1.0 - t * t));
  }
  return 8.0 * (y * y - 1.0);
}

}  // namespace si::cont::test
