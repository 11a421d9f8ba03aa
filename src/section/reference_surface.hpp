// Moving the reference surface of a plate stiffness (vam.md section 6.5, step "shift A_R").
//
// A stiffness [[A, B], [B^T, D]] in the Yu ordering [e11, 2e12, e22, k11, k12+k21, k22]
// relates resultants about a reference surface to the strains of that surface. If the new
// reference lies a distance e above the old one, the old strains are e_old = e_new - e k and
// M_new = M_old - e N, hence (Jones 1999, section 4.2, with z measured from the new surface)
//   A' = A,   B' = B - e A,   D' = D - e (B + B^T) + e^2 A   (= D - 2 e B + e^2 A, B symmetric).
// Shifts compose: shifting by e1 then by e2 equals shifting by e1 + e2.
#pragma once

#include "core/linalg.hpp"

namespace si {

// Stiffness about a reference surface at x3 = offset_mm above the surface `abd_about_mid`
// refers to (normally the mid-surface). The transverse-shear stiffness does not change.
// Throws an input si::Error if the offset is not finite.
Matrix6d shift_reference(const Matrix6d& abd_about_mid, double offset_mm);

}  // namespace si
