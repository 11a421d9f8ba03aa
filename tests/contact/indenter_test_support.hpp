// Shared helpers of the indenter tests: sample points and finite-difference derivatives.
#pragma once

#include <functional>
#include <vector>

#include "contact/indenter.hpp"

namespace si::test {

// A deterministic cloud of points in the box [lo, hi]^3 (n per side, shifted off symmetry
// planes so no point lies on an axis or a region boundary by construction).
inline std::vector<Vector3d> box_points(const Vector3d& lo, const Vector3d& hi, int n) {
  std::vector<Vector3d> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vector3d f((i + 0.37) / n, (j + 0.61) / n, (k + 0.23) / n);
        points.push_back(lo + f.cwiseProduct(hi - lo));
      }
  return points;
}

// Central-difference gradient of a scalar field (step h).
inline Vector3d fd_gradient(const std::function<double(const Vector3d&)>& f, const Vector3d& x,
                            double h = 1e-5) {
  Vector3d g;
  for (int i = 0; i < 3; ++i) {
    Vector3d e = Vector3d::Zero();
    e(i) = h;
    g(i) = (f(x + e) - f(x - e)) / (2 * h);
  }
  return g;
}

// Central-difference Jacobian d n_i / d x_j of the indenter's normal field.
inline Matrix3d fd_normal_jacobian(const Indenter& ind, const Vector3d& x, double travel,
                                   double h = 1e-5) {
  Matrix3d jac;
  for (int j = 0; j < 3; ++j) {
    Vector3d e = Vector3d::Zero();
    e(j) = h;
    Vector3d np, nm;
    ind.signed_distance(x + e, travel, &np, nullptr);
    ind.signed_distance(x - e, travel, &nm, nullptr);
    jac.col(j) = (np - nm) / (2 * h);
  }
  return jac;
}

// Points of a flat n x n grid at height z over [-half, half]^2.
inline std::vector<Vector3d> plate_points(double half, double z, int n) {
  std::vector<Vector3d> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      points.emplace_back(-half + 2 * half * i / (n - 1), -half + 2 * half * j / (n - 1), z);
  return points;
}

}  // namespace si::test
