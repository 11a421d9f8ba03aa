// Quadratic interlaminar criterion for delamination onset (Brewer & Lagace, "Quadratic stress
// criterion for initiation of delamination", J. Compos. Mater. 22 (1988) 1141-1155):
//   (<s33>/Z_T)^2 + (s13/S_13)^2 + (s23/S_23)^2 = 1,      <s33> = max(s33, 0),
// with the interlaminar stresses at an interface (continuous across it) resolved in the material
// axes of a ply that meets it. A compressive normal stress closes the interface and does not
// drive delamination (Brewer & Lagace's compressive term is left out, as in most uses of the
// criterion). On an interface between plies of different angle the caller evaluates both plies'
// axes and keeps the larger index.
#pragma once

#include "damage/criterion_strengths.hpp"
#include "damage/failure_index.hpp"
#include "damage/material_stress.hpp"

namespace si {

FailureIndex quadratic_delamination(const MaterialStress& stress, const Strengths& strengths);

}  // namespace si
