#include "section/clt_section.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "section/reduced_stiffness.hpp"
#include "section/reference_surface.hpp"

namespace si {
namespace {

// Relative closeness of two numbers or matrices, for the mirror test of is_symmetric_layup.
constexpr double kMirrorTol = 1e-12;

Matrix6d clt_abd_about_mid(const Laminate& laminate) {
  // (z_k^2 - z_{k-1}^2)/2 = t zbar and (z_k^3 - z_{k-1}^3)/3 = t zbar^2 + t^3/12: the centroid
  // form keeps B of a symmetric stack at round-off of h * A instead of cancelling z_k^2 terms.
  const auto z = laminate.interfaces();
  Matrix3d A = Matrix3d::Zero(), B = Matrix3d::Zero(), D = Matrix3d::Zero();
  for (size_t k = 0; k < laminate.plies.size(); ++k) {
    const Ply& ply = laminate.plies[k];
    const Matrix3d Q = reduced_stiffness(ply);
    const double t = ply.thickness;
    const double zbar = 0.5 * (z[k] + z[k + 1]);
    A += t * Q;
    B += t * zbar * Q;
    D += (t * zbar * zbar + t * t * t / 12.0) * Q;
  }
  Matrix6d abd;
  abd << A, B, B, D;
  return abd;
}

}  // namespace

Matrix6d clt_abd(const Laminate& laminate) {
  laminate.validate();
  return shift_reference(clt_abd_about_mid(laminate), laminate.reference_offset);
}

Matrix6d swap_yu_conventional_order(const Matrix6d& abd) {
  static constexpr int p[6] = {0, 2, 1, 3, 5, 4};
  return permuted(abd, p);
}

bool is_specially_orthotropic(const Matrix6d& abd, double rel_tol) {
  if (!(rel_tol >= 0.0) || !std::isfinite(rel_tol))
    throw_input("relative tolerance must be non-negative and finite",
                Where{"", "rel_tol", std::to_string(rel_tol), 0});
  const double a_scale = a_block(abd).cwiseAbs().maxCoeff();
  const double d_scale = d_block(abd).cwiseAbs().maxCoeff();
  const double b_scale = std::sqrt(a_scale * d_scale);
  // Yu order: 16 couples 11 with 2e12 (index 0, 1), 26 couples 2e12 with 22 (index 1, 2).
  const bool a_ok =
      std::abs(abd(0, 1)) <= rel_tol * a_scale && std::abs(abd(1, 2)) <= rel_tol * a_scale;
  const bool d_ok =
      std::abs(abd(3, 4)) <= rel_tol * d_scale && std::abs(abd(4, 5)) <= rel_tol * d_scale;
  const bool b_ok = b_block(abd).cwiseAbs().maxCoeff() <= rel_tol * b_scale;
  return a_ok && d_ok && b_ok;
}

bool is_symmetric_layup(const Laminate& laminate) {
  laminate.validate();
  const auto& plies = laminate.plies;
  const size_t n = plies.size();
  for (size_t k = 0; k < n / 2; ++k) {
    const Ply& lo = plies[k];
    const Ply& hi = plies[n - 1 - k];
    const double t_scale = std::max(lo.thickness, hi.thickness);
    if (std::abs(lo.thickness - hi.thickness) > kMirrorTol * t_scale) return false;
    const Matrix6d C_lo = lo.stiffness_yu();
    const Matrix6d C_hi = hi.stiffness_yu();
    if ((C_lo - C_hi).cwiseAbs().maxCoeff() > kMirrorTol * C_lo.cwiseAbs().maxCoeff()) return false;
  }
  return true;
}

}  // namespace si
