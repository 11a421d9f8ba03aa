// Which strain measures an element uses. kNonlinear: Green-Lagrange-type shell strains of the
// first-order kinematics phi = x + zeta d (Simo & Fox 1989), total Lagrangian, large rotations.
// kLinear: the same strains linearised about the reference state (small displacements and
// rotations); shell_element.hpp says how a NodeState is read in that mode.
#pragma once

namespace si {

enum class Kinematics { kLinear, kNonlinear };

}  // namespace si
