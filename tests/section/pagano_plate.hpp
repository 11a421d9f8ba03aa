// Exact 3-D elasticity solution of a simply supported rectangular cross-ply plate under a
// sinusoidal normal load on its top face (Pagano, J. Compos. Mater. 4 (1970) 20-34, "Exact
// solutions for rectangular bidirectional composites and sandwich plates"), evaluated here by the
// state-space (transfer-matrix) form of the same solution: test support, independent of the
// section analysis.
//
// Plate [0, a] x [0, b] x [-h/2, h/2], plies orthotropic in the plate axes (fibre angle 0 or 90
// deg), perfectly bonded. Load: sigma_zz(x, y, h/2) = -q0 sin(p x) sin(r y) (a pressure q0 pushing
// down, along -z), p = pi/a, r = pi/b; the bottom face is free. Edge conditions of Pagano's
// simple support: sigma_xx = v = w = 0 on x = 0, a and sigma_yy = u = w = 0 on y = 0, b. Then
//   u = U(z) cos(px) sin(ry), v = V(z) sin(px) cos(ry), w = W(z) sin(px) sin(ry)
// and 3-D equilibrium reduces, in each ply, to s' = A s for s = [U, V, W, X, Y, Z], where X, Y, Z
// are the amplitudes of tau_xz ~ cos sin, tau_yz ~ sin cos and sigma_zz ~ sin sin. s is continuous
// at interfaces; s(z_top of ply) = exp(A t) s(z_bottom of ply). The face conditions
// X = Y = Z = 0 at the bottom and X = Y = 0, Z = -q0 at the top leave a 3 x 3 linear system for
// U, V, W at the bottom face.
#pragma once

#include <vector>

#include "core/linalg.hpp"
#include "section/laminate.hpp"

namespace si::testing {

// Stress and displacement amplitudes at height z (from the mid-surface). Each is the field at
// the point where its trigonometric factor is 1:
//   sigma_xx, sigma_yy, sigma_zz, w at (a/2, b/2); tau_xy at (0, 0); tau_xz at (0, b/2);
//   tau_yz at (a/2, 0); u at (0, b/2); v at (a/2, 0).
struct PaganoPoint {
  double sigma_xx = 0, sigma_yy = 0, sigma_zz = 0;
  double tau_xy = 0, tau_xz = 0, tau_yz = 0;
  double u = 0, v = 0, w = 0;
};

class PaganoPlate {
 public:
  // Plies must have angle 0 or 90 deg (orthotropic in plate axes); throws std::invalid_argument
  // otherwise.
  PaganoPlate(const Laminate& laminate, double a, double b, double q0);

  // The fields at z; at an interface, `ply` picks the side (default: the ply containing z).
  PaganoPoint at(double z, int ply = -1) const;

 private:
  struct PlyConstants {
    double C11, C12, C13, C22, C23, C33, C44, C55, C66;  // tau_yz: C44, tau_xz: C55
  };
  Matrix6d system_matrix(const PlyConstants& c) const;
  PaganoPoint fields(const PlyConstants& c, const Vector6d& s) const;

  double p_, r_;
  std::vector<double> z_;
  std::vector<PlyConstants> plies_;
  std::vector<Vector6d> bottom_states_;  // s at the bottom face of each ply
};

}  // namespace si::testing
