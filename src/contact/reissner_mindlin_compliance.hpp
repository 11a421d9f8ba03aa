// The normal compliance of a section's Reissner-Mindlin plate (the shell's own model of the
// laminate, flat and infinite) under a pressure p cos(k e.x), e = (cos phi, sin phi): its
// deflection is H p / k cos(k e.x), H in 1/MPa as in layer_compliance.hpp. The plate's
// stiffness for the amplitudes (W cos, B sin) of the deflection and the rotations is
//     [[k.G.k, (G k)^T], [G k, Bk^T D Bk + G]]
// with Bk the curvatures of the rotations' wave, D the classical bending stiffness (bending-
// twisting kept) and G the transverse shear stiffness; H = k times the W-W entry of its inverse.
// At long waves H -> 1 / (k^3 e.D'.e) (Kirchhoff), at short ones -> 1 / (k e.G.e) (shear).
#pragma once

#include "core/linalg.hpp"

namespace si {

// D: the bending block of the section's stiffness in the strain order [k11, k12 + k21, k22]
// (section/vam_section.hpp, A_R rows 3-5), N mm; G: [[G13, .], [., G23]], N/mm; k > 0, 1/mm.
double reissner_mindlin_compliance(const Matrix3d& D, const Matrix2d& G, double phi_rad,
                                   double wavenumber);

}  // namespace si
