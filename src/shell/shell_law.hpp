#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/linalg.hpp"

namespace si {

struct ShellLaw {
  Matrix6d A_R;
  Matrix2d G;
};  // N = A_R R, Q = G gamma (Yu order)
ShellLaw isotropic_shell_law(double E, double nu, double t, double k = 5.0 / 6.0);

}  // namespace si
