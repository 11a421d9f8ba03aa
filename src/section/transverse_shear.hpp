// Transverse-shear stiffness G of a Reissner-Mindlin plate, Q = G * gamma, order
// [Q1, Q2] / [2g13, 2g23] (vam.md sections 1 and 10), units N/mm. Two baselines for the VAM fit:
//
// - fsdt_shear_stiffness: first-order shear deformation theory with a shear correction factor,
//   G = k * integral of the ply transverse-shear stiffness (Reddy 2004, section 3.4; vam.md 10.2).
// - equilibrium_shear_stiffness: the energy-consistent G of Whitney (1973, J. Appl. Mech.
//   40:302), generalised to 2x2 (vam.md 10.3): shear stresses from 3-D equilibrium of CLT
//   bending states, G = (complementary energy matrix)^-1. For a homogeneous plate it is
//   5/6 * G h; for cross-ply stacks it is within a few per cent of the VAM value.
//
// Neither depends on laminate.reference_offset: G relates the shear force to the shear strain,
// neither of which changes when the 2-D reference surface moves (only A, B, D do, through
// shift_reference). The equilibrium profiles are computed from the ABD about the mid-surface.
#pragma once

#include "core/linalg.hpp"
#include "section/laminate.hpp"

namespace si {

// k * sum_k t_k C_s,k with C_s,k the 2x2 transverse-shear block (Yu rows/cols 3, 4) of the ply
// stiffness in plate axes: [[G13 c^2 + G23 s^2, (G13 - G23) c s], [., G13 s^2 + G23 c^2]].
// Throws an input si::Error if k is not positive and finite, or the laminate is invalid.
Matrix2d fsdt_shear_stiffness(const Laminate& laminate, double k = 5.0 / 6.0);

// Whitney-type G (vam.md 10.3): unit states dM11/dx1 = 1 and dM22/dx2 = 1 with all other
// resultant gradients zero; shear stresses tau_a(x3) integrated from the bottom face by 3-D
// equilibrium; F_ab = integral tau_a^T S_s tau_b dx3 with S_s = C_s^-1; G = F^-1.
// Throws an input si::Error for an invalid laminate, a numerical one if ABD or F is singular.
Matrix2d equilibrium_shear_stiffness(const Laminate& laminate);

}  // namespace si
