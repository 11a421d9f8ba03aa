// One complementarity row of the indentation Jacobian as the Krylov solver's preconditioner
// condenses it (contact_jacobian_solver.hpp).
#pragma once

#include <array>

namespace si {

// One complementarity row of J: the candidate's equations (its node's 3 translations and 2
// rotations, -1 if prescribed), its gap gradient G_i on those dofs (spatial increments, before
// the chart), and the derivatives of its NCP row: a = d phi / d lambda_i (its diagonal in J, a
// local law's own compliance included), b = kappa d phi / d(kappa g).
struct ContactJacobianRow {
  std::array<int, 5> eq{-1, -1, -1, -1, -1};
  std::array<double, 5> gradient{0, 0, 0, 0, 0};
  double a = 1.0;
  double b = 0.0;
};

}  // namespace si
