// Resultant constitutive law of the 2-D Reissner-Mindlin shell (paper eqs 1-4, 6-7):
//   N = A_R R,  Q = G gamma,  energy density 1/2 R^T A_R R + 1/2 gamma^T G gamma
// per unit reference mid-surface area. Components in the local Cartesian frame (t1, t2, n) of an
// integration point (shell_element.hpp says how t1 is chosen):
//   R     = [e11, 2 e12, e22, k11, k12 + k21, k22]   (Yu ordering, paper eq 3)
//   gamma = [2 g13, 2 g23]                            (engineering shears, paper eq 4)
//   N     = [N11, N12, N22, M11, M12, M22]  (N/mm, N mm/mm),  Q = [Q1, Q2]  (N/mm).
// A_R may couple membrane and bending (B != 0): nothing below assumes block diagonality.
#pragma once

#include "core/linalg.hpp"

namespace si {

struct ShellLaw {
  Matrix6d A_R = Matrix6d::Zero();
  Matrix2d G = Matrix2d::Zero();
};

// Homogeneous isotropic shell of thickness t (mm), modulus E (MPa), Poisson ratio nu and shear
// correction k: A = E t / (1 - nu^2) [..], D = E t^3 / (12 (1 - nu^2)) [..], G = k E t / (2 (1 +
// nu)). Throws an input error unless E > 0, t > 0, -1 < nu < 0.5, k > 0.
ShellLaw isotropic_shell_law(double E, double nu, double t, double k = 5.0 / 6.0);

}  // namespace si
