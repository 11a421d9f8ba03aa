#include "shell/shell_law.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace si {
namespace {

// Plate theory closed forms: A11 = E t / (1 - nu^2), D11 = E t^3 / (12 (1 - nu^2)),
// A66 = E t / (2 (1 + nu)) on the engineering shear 2e12, G = k E t / (2 (1 + nu)).
TEST(ShellLaw, IsotropicClosedForms) {
  const double E = 1e6, nu = 0.25, t = 0.001;
  const ShellLaw law = isotropic_shell_law(E, nu, t);
  EXPECT_NEAR(law.A_R(0, 0), E * t / (1 - nu * nu), 1e-12);
  EXPECT_NEAR(law.A_R(0, 2), nu * E * t / (1 - nu * nu), 1e-12);
  EXPECT_NEAR(law.A_R(1, 1), E * t / (2 * (1 + nu)), 1e-12);
  EXPECT_NEAR(law.A_R(3, 3), E * t * t * t / (12 * (1 - nu * nu)), 1e-18);
  EXPECT_NEAR(law.A_R(4, 4), E * t * t * t / (24 * (1 + nu)), 1e-18);
  EXPECT_EQ((law.A_R.topRightCorner<3, 3>().norm()), 0);
  EXPECT_NEAR(law.G(0, 0), 5.0 / 6.0 * E * t / (2 * (1 + nu)), 1e-12);
  EXPECT_THROW(isotropic_shell_law(E, 0.5, t), Error);
  EXPECT_THROW(isotropic_shell_law(E, nu, 0), Error);
}

}  // namespace
}  // namespace si
