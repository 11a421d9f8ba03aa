// MITC4 assumed transverse shear strain (Dvorkin & Bathe 1984; Bathe 1996, sec. 5.4):
// the covariant shear gamma_xi is sampled at A = (0,-1) and C = (0,1), gamma_eta at D = (-1,0)
// and B = (1,0), and interpolated linearly:
//   gamma_xi  = (1 - eta)/2 gamma_xi^A  + (1 + eta)/2 gamma_xi^C
//   gamma_eta = (1 - xi)/2  gamma_eta^D + (1 + xi)/2  gamma_eta^B
#pragma once

#include <array>

#include <Eigen/Dense>

namespace si {

struct TyingPoint {
  double xi;
  double eta;
  int component;  // 0 = gamma_xi, 1 = gamma_eta
};

constexpr std::array<TyingPoint, 4> kMitc4TyingPoints = {
    {{0, -1, 0}, {0, 1, 0}, {-1, 0, 1}, {1, 0, 1}}};

// Row c, column t: weight of the value at tying point t in the covariant shear component c at
// (xi, eta). Columns of tying points of the other component are zero.
inline Eigen::Matrix<double, 2, 4> mitc4_shear_interpolation(double xi, double eta) {
  Eigen::Matrix<double, 2, 4> w;
  w << (1 - eta) / 2, (1 + eta) / 2, 0, 0, 0, 0, (1 - xi) / 2, (1 + xi) / 2;
  return w;
}

}  // namespace si
