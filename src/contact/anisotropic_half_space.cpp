#include "contact/anisotropic_half_space.hpp"

#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "material/stiffness_contraction.hpp"

namespace si {
namespace {

// Willis' shape: A = exp(S), S = [[u, v], [v, -u]] (symmetric, traceless: det A = 1), a smooth
// chart around the circle u = v = 0.
Matrix2d ellipse_shape(double u, double v) {
  const double rho = std::hypot(u, v);
  const double sinhc = rho > 1e-8 ? std::sinh(rho) / rho : 1 + rho * rho / 6;
  Matrix2d A;
  A << std::cosh(rho) + sinhc * u, sinhc * v, sinhc * v, std::cosh(rho) - sinhc * u;
  return A;
}

// Willis' integrals over [0, 2pi) from H on [0, pi) (the integrands are pi-periodic).
struct WillisIntegrals {
  Matrix2d K = Matrix2d::Zero();  // int H e e^T / s^3
  double J0 = 0;                  // int H / s
};

WillisIntegrals willis_integrals(const std::vector<double>& H, const Matrix2d& A) {
  const int n = static_cast<int>(H.size());
  const double weight = 2 * kPi / n;  // trapezoidal weight on [0, pi), doubled for [0, 2pi)
  WillisIntegrals w;
  for (int j = 0; j < n; ++j) {
    const double phi = kPi * j / n;
    const Vector2d e(std::cos(phi), std::sin(phi));
    const double s = std::sqrt(e.dot(A * e));
    w.K += weight * H[j] / (s * s * s) * e * e.transpose();
    w.J0 += weight * H[j] / s;
  }
  return w;
}

// Residual of K ~ identity: [(K11 - K22), 2 K12] / trace K.
Vector2d shape_residual(const std::vector<double>& H, const Vector2d& uv) {
  const Matrix2d K = willis_integrals(H, ellipse_shape(uv[0], uv[1])).K;
  return Vector2d(K(0, 0) - K(1, 1), 2 * K(0, 1)) / K.trace();
}

// Newton with a forward-difference Jacobian and step halving; the residual is smooth in (u, v).
Vector2d solve_shape(const std::vector<double>& H) {
  Vector2d uv = Vector2d::Zero();
  Vector2d r = shape_residual(H, uv);
  for (int it = 0; it < 60 && r.norm() > 1e-14; ++it) {
    Matrix2d J;
    for (int c = 0; c < 2; ++c) {
      Vector2d d = uv;
      d[c] += 1e-7;
      J.col(c) = (shape_residual(H, d) - r) / 1e-7;
    }
    const Vector2d step = J.fullPivLu().solve(-r);
    double t = 1;
    Vector2d next = uv + step, r_next = shape_residual(H, next);
    while (r_next.norm() >= r.norm() && t > 1e-4) {
      t /= 2;
      next = uv + t * step;
      r_next = shape_residual(H, next);
    }
    uv = next, r = r_next;
  }
  if (!(r.norm() <= 1e-10))
    throw_numerical("Willis' elliptical contact: the shape did not converge (residual " +
                    std::to_string(r.norm()) + ")");
  return uv;
}

}  // namespace

double half_space_normal_compliance(const Matrix6d& C, double phi_rad, int quadrature) {
  SI_REQUIRE(quadrature >= 8, "half_space_normal_compliance: at least 8 quadrature points");
  const Vector3d e(std::cos(phi_rad), std::sin(phi_rad), 0.0), n(0.0, 0.0, 1.0);
  // The Barnett-Lothe integrand at w.
  const auto integrand = [&](double w) {
    const Vector3d m = std::cos(w) * e + std::sin(w) * n;
    const Vector3d q = -std::sin(w) * e + std::cos(w) * n;
    const Matrix3d mq = stiffness_contraction(C, m, q);
    return Matrix3d(stiffness_contraction(C, m, m) -
                    mq * stiffness_contraction(C, q, q).ldlt().solve(mq.transpose()));
  };
  // Trapezoidal rule on [0, pi), doubled (reusing its points) until H settles to 1e-15: strong
  // anisotropy sharpens the integrand (E1/E3 = 20 needs ~256 points for 1e-12).
  Matrix3d sum = Matrix3d::Zero();
  for (int j = 0; j < quadrature; ++j) sum += integrand(kPi * j / quadrature);
  int n_points = quadrature;
  double H = (sum / n_points).ldlt().solve(n)[2];
  for (; n_points < (1 << 14); n_points *= 2) {
    for (int j = 0; j < n_points; ++j) sum += integrand(kPi * (j + 0.5) / n_points);
    const double refined = (sum / (2 * n_points)).ldlt().solve(n)[2];
    const bool settled = std::abs(refined - H) <= 1e-15 * std::abs(refined);
    H = refined;
    if (settled) break;
  }
  return H;  // L = (1/pi) x the trapezoidal rule's (pi / points) x sum
}

HalfSpaceIndentation half_space_indentation(const Matrix6d& C, double extra_compliance,
                                            int directions) {
  SI_REQUIRE(directions >= 8, "half_space_indentation: at least 8 directions");
  SI_REQUIRE(extra_compliance >= 0, "half_space_indentation: negative indenter compliance");
  std::vector<double> H(directions);
  double mean = 0;
  for (int j = 0; j < directions; ++j) {
    H[j] = half_space_normal_compliance(C, kPi * j / directions) + extra_compliance;
    mean += H[j] / directions;
  }
  HalfSpaceIndentation out;
  out.vlassak_nix = 2 / mean;
  const Vector2d uv = solve_shape(H);
  const WillisIntegrals w = willis_integrals(H, ellipse_shape(uv[0], uv[1]));
  const double J2 = w.K.trace() / 2;
  out.willis = std::pow(2.0, 2.5) * kPi * std::sqrt(J2) / std::pow(w.J0, 1.5);
  const double rho = uv.norm();
  out.aspect = std::exp(-rho);
  double angle = rho > 0 ? 0.5 * std::atan2(uv[1], uv[0]) * 180 / kPi : 0.0;
  if (angle <= -90) angle += 180;
  out.major_axis_deg = angle;
  return out;
}

}  // namespace si
