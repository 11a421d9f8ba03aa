#include "navier_rm_plate.hpp"

#include <cmath>
#include <stdexcept>

namespace si::testing {
namespace {

constexpr double kHalfPi = 1.5707963267948966;

// R components on the sin(px) sin(ry) family (0) or the cos(px) cos(ry) family (1).
constexpr int kFamily[6] = {0, 1, 0, 0, 1, 0};

// d^n/dx^n sin(k x + phase) = k^n sin(k x + phase + n pi/2).
double trig_derivative(double k, double x, double phase, int n) {
  return std::pow(k, n) * std::sin(k * x + phase + n * kHalfPi);
}

}  // namespace

NavierRmPlate::NavierRmPlate(const VamSection& section, double a, double b, double q0)
    : p_(std::acos(-1.0) / a), r_(std::acos(-1.0) / b), q0_(q0) {
  const Matrix6d& A = section.A_R;
  const double scale = A.cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (kFamily[i] != kFamily[j] && std::abs(A(i, j)) > 1e-12 * scale)
        throw std::invalid_argument("Navier solution needs a cross-ply section");
  if (std::abs(section.G(0, 1)) > 1e-12 * section.G.norm() ||
      std::abs(section.Fbar_top(1)) + std::abs(section.Fbar_top(4)) >
          1e-12 * section.Fbar_top.norm())
    throw std::invalid_argument("Navier solution needs a cross-ply section");

  // R-hat = L x and gamma-hat = M x (amplitudes of each component's trigonometric factor).
  const double p = p_, r = r_;
  Eigen::Matrix<double, 6, 5> L = Eigen::Matrix<double, 6, 5>::Zero();
  L(0, 0) = -p;
  L(1, 0) = r;
  L(1, 1) = p;
  L(2, 1) = -r;
  L(3, 3) = -p;
  L(4, 3) = r;
  L(4, 4) = p;
  L(5, 4) = -r;
  Eigen::Matrix<double, 2, 5> M = Eigen::Matrix<double, 2, 5>::Zero();
  M(0, 2) = p;
  M(0, 3) = 1;
  M(1, 2) = r;
  M(1, 4) = 1;
  // Pi / (ab/4) = 1/2 x^T (L^T A L + M^T G M) x + x^T L^T Fbar t - t W, t = -q0.
  const double t = -q0;
  const Eigen::Matrix<double, 5, 5> K = L.transpose() * A * L + M.transpose() * section.G * M;
  Eigen::Matrix<double, 5, 1> f = -L.transpose() * section.Fbar_top * t;
  f(2) += t;
  amplitudes_ = K.fullPivLu().solve(f);
  R_amplitudes_ = L * amplitudes_;
}

NavierRmPlate::NavierRmPlate(const VamSection& section, double a, double b, double q0,
                             const Eigen::Matrix<double, 5, 1>& amplitudes)
    : NavierRmPlate(section, a, b, q0) {
  amplitudes_ = amplitudes;
  const double p = p_, r = r_;
  R_amplitudes_ << -p * amplitudes(0), r * amplitudes(0) + p * amplitudes(1), -r * amplitudes(1),
      -p * amplitudes(3), r * amplitudes(3) + p * amplitudes(4), -r * amplitudes(4);
}

NavierRmPoint NavierRmPlate::at(double x, double y) const {
  // R_i with nx x-derivatives and ny y-derivatives.
  auto R = [&](int nx, int ny) {
    Vector6d out;
    for (int i = 0; i < 6; ++i) {
      const double phase = kFamily[i] == 0 ? 0.0 : kHalfPi;
      out(i) =
          R_amplitudes_(i) * trig_derivative(p_, x, phase, nx) * trig_derivative(r_, y, phase, ny);
    }
    return out;
  };
  NavierRmPoint out;
  out.state.R = R(0, 0);
  out.state.dR = {R(1, 0), R(0, 1)};
  out.state.d2R = std::array<Vector6d, 3>{R(2, 0), R(1, 1), R(0, 2)};
  out.d3R = {R(3, 0), R(2, 1), R(1, 2), R(0, 3)};
  out.state.t_top = -q0_ * std::sin(p_ * x) * std::sin(r_ * y);
  out.state.t_bottom = 0;
  return out;
}

}  // namespace si::testing
