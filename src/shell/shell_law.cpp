#include "shell/shell_law.hpp"

#include "core/error.hpp"

namespace si {

ShellLaw isotropic_shell_law(double E, double nu, double t, double k) {
  SI_REQUIRE(E > 0 && t > 0 && k > 0, "isotropic shell law: E, t and k must be positive");
  SI_REQUIRE(nu > -1 && nu < 0.5, "isotropic shell law: Poisson ratio must lie in (-1, 0.5)");
  Eigen::Matrix3d plane;  // plane-stress stiffness in [11, 2*12, 22] order, per unit modulus
  plane << 1, 0, nu, 0, (1 - nu) / 2, 0, nu, 0, 1;
  plane /= 1 - nu * nu;
  ShellLaw law;
  law.A_R.topLeftCorner<3, 3>() = E * t * plane;
  law.A_R.bottomRightCorner<3, 3>() = E * t * t * t / 12 * plane;
  law.G = Matrix2d::Identity() * k * E * t / (2 * (1 + nu));
  return law;
}

}  // namespace si
