#include "material/material.hpp"

#include <gtest/gtest.h>

#include "material_fixtures.hpp"

#include <cmath>
#include <functional>
#include <string>

#include "core/error.hpp"

namespace si {
namespace {

using testing::generic_constants;
using testing::max_abs;

TEST(Material, ComplianceTimesStiffnessIsIdentity) {
  for (const Material& m : {Material::orthotropic("generic", generic_constants()),
                            Material::isotropic("steel", 210000, 0.3)}) {
    const Matrix6d I = m.compliance() * m.stiffness();
    EXPECT_LE(max_abs(I - Matrix6d::Identity()), 1e-13) << m.name() << "\n" << I;
    EXPECT_EQ(m.stiffness(), m.stiffness().transpose());
  }
}

// Compliance entries as stated in vam.md section 1, and the reciprocity nu_ij/E_i = nu_ji/E_j
// that makes the compliance symmetric.
TEST(Material, ComplianceEntries_VamSection1) {
  const EngineeringConstants c = generic_constants();
  const Matrix6d S = Material::orthotropic("generic", c).compliance();
  EXPECT_DOUBLE_EQ(S(0, 0), 1 / c.E1);
  EXPECT_DOUBLE_EQ(S(2, 2), 1 / c.E3);
  EXPECT_DOUBLE_EQ(S(1, 2), -c.nu23 / c.E2);
  EXPECT_DOUBLE_EQ(S(3, 3), 1 / c.G23);  // Voigt 4 = 23
  EXPECT_DOUBLE_EQ(S(4, 4), 1 / c.G13);  // Voigt 5 = 13
  EXPECT_DOUBLE_EQ(S(5, 5), 1 / c.G12);  // Voigt 6 = 12
  EXPECT_EQ(S, S.transpose());
}

// Isotropic solid: G = E/(2(1+nu)) and the Lame form C11 = E(1-nu)/((1+nu)(1-2nu)),
// C12 = E nu/((1+nu)(1-2nu)) (any elasticity text, e.g. Timoshenko & Goodier, section 6).
TEST(Material, IsotropicClosedForm) {
  const double E = 210000, nu = 0.3;
  const Material m = Material::isotropic("steel", E, nu);
  const double G = E / (2 * (1 + nu));
  EXPECT_TRUE(m.is_isotropic());
  EXPECT_DOUBLE_EQ(m.constants().G12, G);
  const Matrix6d C = m.stiffness();
  const double lame = E / ((1 + nu) * (1 - 2 * nu));
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(C(i, i), lame * (1 - nu), 1e-12 * lame);
    EXPECT_NEAR(C(i, (i + 1) % 3), lame * nu, 1e-12 * lame);
    EXPECT_NEAR(C(i + 3, i + 3), G, 1e-12 * G);
  }
}

// Runs `make`, expects an input si::Error whose where().key is `key`.
void expect_rejected(const std::function<void()>& make, const std::string& key) {
  try {
    make();
    ADD_FAILURE() << "accepted invalid " << key;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput) << e.what();
    EXPECT_EQ(e.where().key, key) << e.what();
  }
}

void expect_orthotropic_rejected(const std::function<void(EngineeringConstants&)>& edit,
                                 const std::string& key) {
  EngineeringConstants c = generic_constants();
  edit(c);
  expect_rejected([&] { Material::orthotropic("bad", c); }, key);
}

TEST(Material, RejectsNonPositiveModuli) {
  expect_orthotropic_rejected([](auto& c) { c.E1 = 0; }, "E1");
  expect_orthotropic_rejected([](auto& c) { c.E2 = -1; }, "E2");
  expect_orthotropic_rejected([](auto& c) { c.E3 = std::nan(""); }, "E3");
  expect_orthotropic_rejected([](auto& c) { c.G12 = 0; }, "G12");
  expect_orthotropic_rejected([](auto& c) { c.G13 = -5; }, "G13");
  expect_orthotropic_rejected([](auto& c) { c.G23 = 0; }, "G23");
}

// Lempriere (1968): |nu_ij| < sqrt(E_i/E_j). The bound itself is rejected (strict inequality).
TEST(Material, RejectsPoissonRatiosBeyondLempriereBound) {
  expect_orthotropic_rejected([](auto& c) { c.nu12 = std::sqrt(c.E1 / c.E2); }, "nu12");
  expect_orthotropic_rejected([](auto& c) { c.nu12 = -4.0; }, "nu12");
  expect_orthotropic_rejected([](auto& c) { c.nu13 = std::sqrt(c.E1 / c.E3) + 1e-9; }, "nu13");
  expect_orthotropic_rejected([](auto& c) { c.nu23 = -std::sqrt(c.E2 / c.E3); }, "nu23");
  // Just inside the bound is accepted when the set stays positive definite.
  EngineeringConstants c = generic_constants();
  c.nu23 = 0.9 * std::sqrt(c.E2 / c.E3);
  c.nu12 = c.nu13 = 0;
  EXPECT_NO_THROW(Material::orthotropic("ok", c));
}

// Each ratio within its bound but the set not positive definite: equal moduli, nu12 = nu13 =
// 0.49, nu23 = 0.99 gives 1 - 0.2401 - 0.9801 - 0.2401 - 2(0.49)(0.99)(0.49) < 0.
TEST(Material, RejectsNonPositiveDefiniteSet) {
  EngineeringConstants c;
  c.E1 = c.E2 = c.E3 = 10000;
  c.G12 = c.G13 = c.G23 = 4000;
  c.nu12 = 0.49;
  c.nu13 = 0.49;
  c.nu23 = 0.99;
  expect_rejected([&] { Material::orthotropic("bad", c); }, "nu12, nu13, nu23");
}

TEST(Material, IsotropicRejectsOutOfRange) {
  expect_rejected([] { Material::isotropic("bad", 0, 0.3); }, "E");
  expect_rejected([] { Material::isotropic("bad", 1000, 0.5); }, "nu");
  expect_rejected([] { Material::isotropic("bad", 1000, -1.0); }, "nu");
  expect_rejected([] { Material::isotropic("bad", 1000, std::nan("")); }, "nu");
  EXPECT_NO_THROW(Material::isotropic("auxetic", 1000, -0.99));
  EXPECT_NO_THROW(Material::isotropic("rubbery", 1000, 0.4999));
}

}  // namespace
}  // namespace si
