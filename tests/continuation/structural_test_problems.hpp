// Small structural continuation problems with closed-form critical points, each providing its
// stability through the library's tools (analyse_stability on its tangent K and constraint rows
// A), the way a finite-element problem would:
//   VonMisesTruss     two bars, apex load: symmetric snap-through, limit load in closed form
//   RigidBarColumn    a rigid bar on a rotational spring, tip load, the bar's length kept by a
//                     Lagrange multiplier: bifurcation at P = k/L, post-buckled P = k t/(L sin t)
//   BeamOnFoundation  a finite-difference beam on an elastic foundation, supports by Lagrange
//                     multipliers: bifurcation loads and sine modes of the discrete problem
#pragma once

#include <cmath>

#include "continuation/stability_analysis.hpp"
#include "dense_test_problems.hpp"

namespace si::cont::test {

// x = [v ; mu]: the first structure_size() unknowns are displacements with symmetric tangent K,
// the rest Lagrange multipliers of the constraint rows A (A v = 0 linearised). The Jacobian is
// [K A'; A 0]. Stability: analyse_stability(K, A), modes completed by multiplier_direction().
class StructuralProblem : public DenseProblem {
 public:
  virtual int structure_size() const = 0;
  virtual Matrix tangent(const Vector& x, double p) const = 0;  // K
  virtual Matrix constraint_rows(const Vector& /*x*/) const {   // A
    return Matrix(0, structure_size());
  }

  Matrix jacobian(const Vector& x, double p) const override {
    const Matrix K = tangent(x, p);
    const Matrix A = constraint_rows(x);
    const auto n = K.rows();
    const auto m = A.rows();
    Matrix J = Matrix::Zero(n + m, n + m);
    J.topLeftCorner(n, n) = K;
    J.topRightCorner(n, m) = A.transpose();
    J.bottomLeftCorner(m, n) = A;
    return J;
  }
  bool provides_stability() const override { return true; }
  bool stability(const Vector& x, double p, int modes, Stability& out) override {
    ++stability_calls_;
    const SparseMatrix K = tangent(x, p).sparseView();
    const SparseMatrix A = constraint_rows(x).sparseView();
    if (!analyse_stability(K, A, modes, out)) return false;
    for (auto& mode : out.modes) {
      Vector full = Vector::Zero(size());
      full.head(K.rows()) = mode;
      if (A.rows() > 0) full.tail(A.rows()) = multiplier_direction(K, A, mode);
      mode = full;
    }
    return true;
  }
  int stability_calls() const { return stability_calls_; }

 private:
  int stability_calls_ = 0;
};

// Two bars of axial stiffness EA from (-b, 0) and (b, 0) to the apex (u, a - w), load P down at
// the apex; x = (u, w). Pi = sum EA/(2L) (l_i - L)^2 - P w. On the symmetric path (u = 0) the load
// is P(w) = 2 EA (a - w)(1/l - 1/L), l^2 = b^2 + (a - w)^2, with maximum where l^3 = b^2 L:
//     P* = 2 EA c* (1/l* - 1/L),  l* = (b^2 L)^(1/3),  c* = (l*^2 - b^2)^(1/2)
// and by antisymmetry about w = a the minimum -P* at w = 2a - (a - c*). Shallow (a << b): the
// sway stiffness stays positive, so both are limit points, not bifurcations.
class VonMisesTruss final : public StructuralProblem {
 public:
  VonMisesTruss(double a, double b, double ea) : a_(a), b_(b), ea_(ea), L_(std::hypot(a, b)) {}
  double limit_load() const {
    const double l = std::cbrt(b_ * b_ * L_);
    const double c = std::sqrt(l * l - b_ * b_);
    return 2.0 * ea_ * c * (1.0 / l - 1.0 / L_);
  }
  double limit_deflection() const {
    const double l = std::cbrt(b_ * b_ * L_);
    return a_ - std::sqrt(l * l - b_ * b_);
  }
  int size() const override { return 2; }
  int structure_size() const override { return 2; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F = Vector::Zero(2);
    for (double side : {1.0, -1.0}) {
      const Eigen::Vector2d d(x(0) + side * b_, a_ - x(1));
      const double l = d.norm();
      const double N = ea_ * (l - L_) / L_;
      F(0) += N * d(0) / l;
      F(1) -= N * d(1) / l;
    }
    F(1) -= p;
    return true;
  }
  bool residual_p(const Vector& /*x*/, double /*p*/, Vector& out) override {
    out = Vector{{0.0, -1.0}};
    return true;
  }
  Matrix tangent(const Vector& x, double /*p*/) const override {
    const Eigen::Matrix2d T = Eigen::Vector2d(1.0, -1.0).asDiagonal();
    Eigen::Matrix2d K = Eigen::Matrix2d::Zero();
    for (double side : {1.0, -1.0}) {
      const Eigen::Vector2d d(x(0) + side * b_, a_ - x(1));
      const double l = d.norm();
      const Eigen::Vector2d n = d / l;
      const double N = ea_ * (l - L_) / L_;
      const Eigen::Matrix2d nn = n * n.transpose();
      K += T * (ea_ / L_ * nn + N / l * (Eigen::Matrix2d::Identity() - nn)) * T;
    }
    return K;
  }
  std::vector<std::string> monitor_names() const override { return {"w", "P"}; }
  Vector monitors(const Vector& x, double p) override { return Vector{{x(1), p}}; }

 private:
  double a_, b_, ea_, L_;
};

// A rigid bar of length L pinned at the origin, a rotational spring k at the pin, a downward load
// P at the tip (u, v); x = (u, v, mu). Pi = k theta^2 / 2 + P v, theta = atan2(u, v), with the
// constraint c = (u^2 + v^2 - L^2) / (2L) = 0 by the multiplier mu. Trivial branch u = 0, v = L,
// mu = -P; the tangent restricted to the constraint is k/L^2 - P/L: a pitchfork at P = k/L, and
// the post-buckled branch P = k theta / (L sin theta), stable (its restricted tangent is
// (k - P L cos theta)/L^2 = k (1 - theta cot theta)/L^2 > 0).
class RigidBarColumn final : public StructuralProblem {
 public:
  RigidBarColumn(double k, double L) : k_(k), L_(L) {}
  double critical_load() const { return k_ / L_; }
  static double angle(const Vector& x) { return std::atan2(x(0), x(1)); }
  int size() const override { return 3; }
  int structure_size() const override { return 2; }
  bool residual(const Vector& x, double p, Vector& F) override {
    const double u = x(0);
    const double v = x(1);
    const double r2 = u * u + v * v;
    const double t = angle(x);
    F.resize(3);
    F(0) = k_ * t * v / r2 + x(2) * u / L_;
    F(1) = -k_ * t * u / r2 + p + x(2) * v / L_;
    F(2) = (r2 - L_ * L_) / (2.0 * L_);
    return true;
  }
  bool residual_p(const Vector& /*x*/, double /*p*/, Vector& out) override {
    out = Vector{{0.0, 1.0, 0.0}};
    return true;
  }
  Matrix tangent(const Vector& x, double /*p*/) const override {
    const double u = x(0);
    const double v = x(1);
    const double r2 = u * u + v * v;
    const double t = angle(x);
    const Eigen::Vector2d grad(v / r2, -u / r2);
    Eigen::Matrix2d hess;
    hess << -2.0 * u * v, u * u - v * v, u * u - v * v, 2.0 * u * v;
    hess /= r2 * r2;
    return k_ * (grad * grad.transpose() + t * hess) + x(2) / L_ * Eigen::Matrix2d::Identity();
  }
  Matrix constraint_rows(const Vector& x) const override { return Matrix{{x(0) / L_, x(1) / L_}}; }
  std::vector<std::string> monitor_names() const override { return {"theta", "P"}; }
  Vector monitors(const Vector& x, double p) override { return Vector{{angle(x), p}}; }

 private:
  double k_, L_;
};

// A beam of bending stiffness EI and length l on a foundation of modulus c under axial
// compression P, N finite-difference intervals (h = l/N), nodes 0..N with deflections w_i; the
// supports w_0 = w_N = 0 by multipliers; x = (w_0..w_N, mu_0, mu_N). Energy
//     EI/2 h sum_{i=1}^{N-1} ((w_{i-1} - 2 w_i + w_{i+1})/h^2)^2 + c/2 h sum w_i^2
//   - P/2 h sum_{i=0}^{N-1} ((w_{i+1} - w_i)/h)^2
// (zero curvature at the supports: simply supported). Linear in w, so w = 0 for every P; the
// sines w_i = sin(m pi i/N) are its exact modes, with the discrete buckling loads
//     P_m = 4 EI s^2 / h^2 + c h^2 / (4 s^2),  s = sin(m pi / (2N)),
// which tend to the continuum EI (m pi/l)^2 + c (l/(m pi))^2 as O(h^2).
class BeamOnFoundation final : public StructuralProblem {
 public:
  BeamOnFoundation(int intervals, double length, double ei, double c)
      : n_(intervals), h_(length / intervals), l_(length), ei_(ei), c_(c) {
    const int nodes = n_ + 1;
    stiffness_ = Matrix::Zero(nodes, nodes);
    geometric_ = Matrix::Zero(nodes, nodes);
    for (int i = 1; i < n_; ++i) {
      const Eigen::Vector3d d(1.0, -2.0, 1.0);
      stiffness_.block(i - 1, i - 1, 3, 3) += ei_ / (h_ * h_ * h_) * d * d.transpose();
    }
    stiffness_.diagonal().array() += c_ * h_;
    for (int i = 0; i < n_; ++i) {
      const Eigen::Vector2d e(-1.0, 1.0);
      geometric_.block(i, i, 2, 2) += e * e.transpose() / h_;
    }
  }
  double discrete_load(int m) const {
    const double s = std::sin(m * std::acos(-1.0) / (2.0 * n_));
    return 4.0 * ei_ * s * s / (h_ * h_) + c_ * h_ * h_ / (4.0 * s * s);
  }
  double continuum_load(int m) const {
    const double k = m * std::acos(-1.0) / l_;
    return ei_ * k * k + c_ / (k * k);
  }
  const Matrix& stiffness() const { return stiffness_; }  // K_E + K_c
  const Matrix& geometric() const { return geometric_; }  // K_G
  int size() const override { return n_ + 3; }
  int structure_size() const override { return n_ + 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    const Vector w = x.head(n_ + 1);
    F.resize(size());
    F.head(n_ + 1) = (stiffness_ - p * geometric_) * w;
    F(0) += x(n_ + 1);
    F(n_) += x(n_ + 2);
    F(n_ + 1) = w(0);
    F(n_ + 2) = w(n_);
    return true;
  }
  bool residual_p(const Vector& x, double /*p*/, Vector& out) override {
    out = Vector::Zero(size());
    out.head(n_ + 1) = -geometric_ * x.head(n_ + 1);
    return true;
  }
  Matrix tangent(const Vector& /*x*/, double p) const override {
    return stiffness_ - p * geometric_;
  }
  Matrix constraint_rows(const Vector& /*x*/) const override {
    Matrix A = Matrix::Zero(2, n_ + 1);
    A(0, 0) = 1.0;
    A(1, n_) = 1.0;
    return A;
  }

 private:
  int n_;
  double h_, l_, ei_, c_;
  Matrix stiffness_;
  Matrix geometric_;
};

}  // namespace si::cont::test
