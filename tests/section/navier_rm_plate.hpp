// The Navier solution of the 2-D Reissner-Mindlin plate of a VAM section (A_R, G and the load
// coupling Fbar of vam.md 7.4) for the simply supported cross-ply plate of pagano_plate.hpp:
// the same plate and load (t+ = -q0 sin(px) sin(ry) on the top face), the same edge conditions.
// Test support: it gives R and its derivatives of any order in closed form, which is what the 3-D
// recovery would get from an exact 2-D solution.
//
// Amplitudes x = [U, V, W, B1, B2] of u1 = U cos sin, u2 = V sin cos, u3 = W sin sin,
// beta1 = B1 cos sin, beta2 = B2 sin cos minimise the 2-D energy of vam.md 7.4 (per quarter of
// the plate area), which needs A_R, G and Fbar without couplings between the sin-sin and cos-cos
// families (cross-ply: A16 = A26 = B16 = B26 = D16 = D26 = 0, G12 = 0, no twist in Fbar).
#pragma once

#include <array>

#include "core/linalg.hpp"
#include "section/through_thickness_recovery.hpp"
#include "section/vam_section.hpp"

namespace si::testing {

// R and its derivatives at one point. dR[a] = R_,a; d2R = R_,11, R_,12, R_,22;
// d3R = R_,111, R_,112, R_,122, R_,222.
struct NavierRmPoint {
  PlateState state;  // R, R_,a, R_,ab (d2R set) and t+
  std::array<Vector6d, 4> d3R;
};

class NavierRmPlate {
 public:
  // Throws std::invalid_argument if the section couples the two trigonometric families.
  NavierRmPlate(const VamSection& section, double a, double b, double q0);
  // The same fields from given amplitudes x = [U, V, W, B1, B2] (e.g. averages of an exact 3-D
  // solution), for comparisons that take the 2-D solution's own error out.
  NavierRmPlate(const VamSection& section, double a, double b, double q0,
                const Eigen::Matrix<double, 5, 1>& amplitudes);

  NavierRmPoint at(double x, double y) const;
  // Thickness-average deflection amplitude W (u3 at the centre).
  double centre_deflection() const { return amplitudes_(2); }

 private:
  double p_, r_, q0_;
  Eigen::Matrix<double, 5, 1> amplitudes_;
  Vector6d R_amplitudes_;
};

}  // namespace si::testing
