// Tsai-Wu criterion, 3-D (S.W. Tsai & E.M. Wu, "A general theory of strength for anisotropic
// materials", J. Compos. Mater. 5 (1971) 58-80), for a ply orthotropic in its material axes:
//   F = F1 s11 + F2 s22 + F3 s33 + F11 s11^2 + F22 s22^2 + F33 s33^2
//       + F44 s23^2 + F55 s13^2 + F66 s12^2 + 2 F12 s11 s22 + 2 F13 s11 s33 + 2 F23 s22 s33
// with F1 = 1/X_T - 1/X_C, F11 = 1/(X_T X_C) (likewise 2 with Y, 3 with Z),
// F44 = 1/S_23^2, F55 = 1/S_13^2, F66 = 1/S_12^2.
// Interaction terms: F_ij = -1/2 sqrt(F_ii F_jj) (Tsai & Hahn, Introduction to Composite
// Materials, 1980: the von Mises-like choice F12* = -1/2, which keeps the quadratic form positive
// definite and needs no biaxial test). Onset at F = 1. The criterion has no modes; the mode
// reported is that of the largest single-component contribution F_i s_i + F_ii s_i^2 (or
// F_jj s_j^2 for a shear), with the sign of the normal stress selecting tension or compression.
#pragma once

#include "damage/criterion_strengths.hpp"
#include "damage/failure_index.hpp"
#include "damage/material_stress.hpp"

namespace si {

FailureIndex tsai_wu(const MaterialStress& stress, const Strengths& strengths);

}  // namespace si
