// Maximum stress criterion, 3-D: each material-axis stress against its own strength, no
// interaction (e.g. Jones, Mechanics of Composite Materials, 2nd ed. 1999, section 2.9.2):
//   index = max( s11/X_T or -s11/X_C, s22/Y_T or -s22/Y_C, s33/Z_T or -s33/Z_C,
//                |s12|/S_12, |s13|/S_13, |s23|/S_23 ),
// linear in the load, so index and published value coincide. The mode is the governing ratio.
#pragma once

#include "damage/criterion_strengths.hpp"
#include "damage/failure_index.hpp"
#include "damage/material_stress.hpp"

namespace si {

FailureIndex max_stress(const MaterialStress& stress, const Strengths& strengths);

}  // namespace si
