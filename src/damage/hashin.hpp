// Hashin's 3-D failure criterion for unidirectional plies (Z. Hashin, "Failure criteria for
// unidirectional fiber composites", J. Appl. Mech. 47 (1980) 329-334, eqs 20-27), four modes with
// the transversely isotropic invariants of the stress (axis 1 = fibre):
//   fibre tension      (s11 > 0):  (s11/X_T)^2 + (s12^2 + s13^2)/S_12^2                   (eq 20)
//   fibre compression  (s11 < 0):  (s11/X_C)^2                                            (eq 21)
//   matrix tension     (s22 + s33 >= 0):
//       (s22 + s33)^2/Y_T^2 + (s23^2 - s22 s33)/S_23^2 + (s12^2 + s13^2)/S_12^2           (eq 22)
//   matrix compression (s22 + s33 < 0):
//       [(Y_C/(2 S_23))^2 - 1] (s22 + s33)/Y_C + (s22 + s33)^2/(4 S_23^2)
//       + (s23^2 - s22 s33)/S_23^2 + (s12^2 + s13^2)/S_12^2                               (eq 23)
// each = 1 at onset. S_12 is Hashin's axial shear strength tau_A (the 12 and 13 planes alike by
// transverse isotropy), S_23 his transverse shear strength tau_T. The fibre mode of the sign of
// s11 and the matrix mode of the sign of s22 + s33 are evaluated; the larger index governs.
#pragma once

#include "damage/criterion_strengths.hpp"
#include "damage/failure_index.hpp"
#include "damage/material_stress.hpp"

namespace si {

FailureIndex hashin(const MaterialStress& stress, const Strengths& strengths);

// The two active modes separately (fibre first, then matrix), for output per mode.
FailureIndex hashin_fibre(const MaterialStress& stress, const Strengths& strengths);
FailureIndex hashin_matrix(const MaterialStress& stress, const Strengths& strengths);

}  // namespace si
