// The ply failure criteria against hand-computed values of their published formulas (Hashin 1980
// eqs 20-23, Tsai & Wu 1971 with Tsai & Hahn's F_ij = -1/2 sqrt(F_ii F_jj), the maximum stress
// criterion, Brewer & Lagace 1988): every Hashin mode exactly at onset and just below, the
// index as the inverse load factor, and the states that must NOT report failure.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "damage/criterion_strengths.hpp"
#include "damage/failure_criterion.hpp"
#include "damage/hashin.hpp"
#include "damage/material_stress.hpp"
#include "damage/max_stress.hpp"
#include "damage/quadratic_delamination.hpp"
#include "damage/tsai_wu.hpp"
#include "material/material_library.hpp"

namespace si {
namespace {

using M = FailureMode;

// Round strengths for hand computation (MPa): X_T, X_C, Y_T, Y_C, Z_T, Z_C, S_12, S_13, S_23.
// Y_C / (2 S_23) = 2, so Hashin's matrix-compression linear coefficient is (4 - 1)/Y_C = 3/200.
const Strengths kS{2000, 1200, 50, 200, 40, 220, 80, 90, 50};

MaterialStress stress(double s11, double s22, double s33, double s12, double s13, double s23) {
  return {s11, s22, s33, s12, s13, s23};
}

void expect_at_onset(const FailureIndex& f, FailureMode mode, const char* what) {
  EXPECT_NEAR(f.criterion_value, 1.0, 1e-14) << what;
  EXPECT_NEAR(f.index, 1.0, 1e-14) << what;
  EXPECT_EQ(f.mode, mode) << what;
}

// Each of Hashin's four modes (eqs 20-23) exactly at 1, built from round numbers:
//   fibre tension      (1200/2000)^2 + 64^2/80^2 = 0.36 + 0.64
//   fibre compression  (-1200/1200)^2, whatever the matrix stresses
//   matrix tension     (30 + 10)^2/50^2 + (20^2 - 30*10)/50^2 + (32^2 + 32^2)/80^2
//                      = 0.64 + 0.04 + 0.32 (3-D: s22, s33, s23, s12, s13 all active)
//   matrix compression (3/200)(-100 - 100) + (-200)^2/(4*50^2) + (0 - 100*100)/50^2 + 160^2/80^2
//                      = -3 + 4 - 4 + 4
// and 0.999 times each state: the published value is then below 1 and the index 0.999.
TEST(HashinCriterion, EachModeExactlyAtOneAndJustBelow) {
  struct Case {
    const char* name;
    MaterialStress s;
    FailureMode mode;
    double value_below;  // published value at 0.999 times the state
  };
  const double b = 3.0 / 200 * -200;  // matrix compression: linear part at the state
  const Case cases[] = {
      {"fibre tension", stress(1200, 0, 0, 64, 0, 0), M::kFibreTension, 0.999 * 0.999},
      {"fibre compression", stress(-1200, 5, -3, 10, 0, 0), M::kFibreCompression, 0.999 * 0.999},
      {"matrix tension", stress(0, 30, 10, 32, 32, 20), M::kMatrixTension, 0.999 * 0.999},
      {"matrix compression", stress(0, -100, -100, 160, 0, 0), M::kMatrixCompression,
       0.999 * b + 0.999 * 0.999 * (1 - b)},
  };
  for (const Case& c : cases) {
    expect_at_onset(hashin(c.s, kS), c.mode, c.name);
    const FailureIndex below = hashin(scaled(c.s, 0.999), kS);
    EXPECT_NEAR(below.criterion_value, c.value_below, 1e-14) << c.name;
    EXPECT_LT(below.criterion_value, 1.0) << c.name;
    EXPECT_NEAR(below.index, 0.999, 1e-14) << c.name;
    EXPECT_EQ(below.mode, c.mode) << c.name;
  }
}

// Hashin's matrix compression has a linear term: at half the transverse compressive strength the
// published value is (3/200)(-100) + 100^2/(4*50^2) = -0.5, the load factor to onset is 2.
TEST(HashinCriterion, MatrixCompressionIndexIsTheInverseLoadFactor) {
  const FailureIndex f = hashin(stress(0, -100, 0, 0, 0, 0), kS);
  EXPECT_NEAR(f.criterion_value, -0.5, 1e-15);
  EXPECT_NEAR(f.index, 0.5, 1e-15);
  EXPECT_EQ(f.mode, M::kMatrixCompression);
  EXPECT_NEAR(hashin(stress(0, -200, 0, 0, 0, 0), kS).criterion_value, 1.0, 1e-15);
}

// The fibre mode of the sign of s11 and the matrix mode of the sign of s22 + s33; the larger
// governs, and both are available separately.
TEST(HashinCriterion, GoverningModeIsTheLargerOfFibreAndMatrix) {
  const MaterialStress s = stress(1000, 25, 0, 0, 0, 0);  // fibre 0.25, matrix 0.25: sqrt -> 0.5
  EXPECT_NEAR(hashin_fibre(s, kS).index, 0.5, 1e-15);
  EXPECT_NEAR(hashin_matrix(s, kS).index, 0.5, 1e-15);
  const MaterialStress t = stress(1000, 30, 0, 0, 0, 0);
  EXPECT_EQ(hashin(t, kS).mode, M::kMatrixTension);
  EXPECT_NEAR(hashin(t, kS).index, 0.6, 1e-15);
  const MaterialStress u = stress(-900, -60, 0, 0, 0, 0);  // fibre 0.75; matrix (3/200)(-60)+...
  EXPECT_EQ(hashin(u, kS).mode, M::kFibreCompression);
  EXPECT_NEAR(hashin(u, kS).index, 0.75, 1e-15);
}

// What must NOT be reported: no stress; transverse hydrostatic compression (Hashin's quadratic
// form vanishes and the linear term is negative, so no load factor reaches onset); fibre-direction
// compression far below X_C with no matrix stress.
TEST(HashinCriterion, ReportsNoFailureWhereThereIsNone) {
  const FailureIndex zero = hashin(stress(0, 0, 0, 0, 0, 0), kS);
  EXPECT_EQ(zero.index, 0.0);
  EXPECT_EQ(zero.mode, M::kNone);
  const FailureIndex hydrostatic = hashin(stress(0, -300, -300, 0, 0, 0), kS);
  EXPECT_EQ(hydrostatic.index, 0.0);
  EXPECT_EQ(hydrostatic.mode, M::kNone);
  EXPECT_LT(hashin(stress(-600, 0, 0, 0, 0, 0), kS).index, 0.5 + 1e-15);
}

// Every strength alone gives index 1 with its mode; the largest ratio governs.
TEST(MaxStressCriterion, EachStrengthAloneIsOnsetWithItsMode) {
  const struct {
    MaterialStress s;
    FailureMode mode;
  } cases[] = {
      {stress(2000, 0, 0, 0, 0, 0), M::kFibreTension},
      {stress(-1200, 0, 0, 0, 0, 0), M::kFibreCompression},
      {stress(0, 50, 0, 0, 0, 0), M::kMatrixTension},
      {stress(0, -200, 0, 0, 0, 0), M::kMatrixCompression},
      {stress(0, 0, 40, 0, 0, 0), M::kNormalTension},
      {stress(0, 0, -220, 0, 0, 0), M::kNormalCompression},
      {stress(0, 0, 0, -80, 0, 0), M::kShear12},
      {stress(0, 0, 0, 0, 90, 0), M::kShear13},
      {stress(0, 0, 0, 0, 0, -50), M::kShear23},
  };
  for (const auto& c : cases) expect_at_onset(max_stress(c.s, kS), c.mode, "max stress");
  // 600/1200 = 0.5, 30/50 = 0.6, 45/90 = 0.5: transverse tension governs at 0.6.
  const FailureIndex f = max_stress(stress(-600, 30, 0, 0, 45, 0), kS);
  EXPECT_NEAR(f.index, 0.6, 1e-15);
  EXPECT_EQ(f.mode, M::kMatrixTension);
  EXPECT_EQ(max_stress(stress(0, 0, 0, 0, 0, 0), kS).mode, M::kNone);
}

// Tsai-Wu: uniaxial states at their strengths are onset (F1 X + F11 X^2 = 1); a biaxial and a
// general 3-D state against the formula evaluated by hand (python, 17 digits):
//   F1 = 1/2000 - 1/1200, F2 = 1/50 - 1/200, F3 = 1/40 - 1/220, F11 = 1/(2000*1200), ...,
//   F12 = -sqrt(F11 F22)/2, ...
//   (500, 20, 0, 0, 0, 0):       F = 0.2129502775632097, index 0.3566000877728248
//   (-300, -60, 10, 30, 20, 15): F = 0.06183059207505359, index 0.565943188997116
TEST(TsaiWuCriterion, UniaxialStrengthsAndHandComputedStates) {
  for (const MaterialStress& s :
       {stress(2000, 0, 0, 0, 0, 0), stress(-1200, 0, 0, 0, 0, 0), stress(0, 50, 0, 0, 0, 0),
        stress(0, -200, 0, 0, 0, 0), stress(0, 0, 40, 0, 0, 0), stress(0, 0, -220, 0, 0, 0),
        stress(0, 0, 0, 80, 0, 0), stress(0, 0, 0, 0, -90, 0), stress(0, 0, 0, 0, 0, 50)}) {
    const FailureIndex f = tsai_wu(s, kS);
    EXPECT_NEAR(f.criterion_value, 1.0, 1e-14);
    EXPECT_NEAR(f.index, 1.0, 1e-14);
  }
  const FailureIndex a = tsai_wu(stress(500, 20, 0, 0, 0, 0), kS);
  EXPECT_NEAR(a.criterion_value, 0.2129502775632097, 1e-15);
  EXPECT_NEAR(a.index, 0.3566000877728248, 1e-15);
  EXPECT_EQ(a.mode, M::kMatrixTension);  // F2 s22 + F22 s22^2 = 0.34 is the largest term
  const FailureIndex b = tsai_wu(stress(-300, -60, 10, 30, 20, 15), kS);
  EXPECT_NEAR(b.criterion_value, 0.06183059207505359, 1e-15);
  EXPECT_NEAR(b.index, 0.565943188997116, 1e-15);
  // Scaling the state by 1/index brings it exactly to onset.
  EXPECT_NEAR(tsai_wu(scaled(stress(-300, -60, 10, 30, 20, 15), 1 / b.index), kS).criterion_value,
              1.0, 1e-13);
  EXPECT_EQ(tsai_wu(stress(0, 0, 0, 0, 0, 0), kS).index, 0.0);
}

// Brewer & Lagace: (20/40)^2 + (45/90)^2 + (25 sqrt2/50)^2 = 1; a compressive sigma33 closes the
// interface and does not count; (20/40)^2 + (45/90)^2 + (25/50)^2 = 0.75.
TEST(QuadraticDelaminationCriterion, OnsetAndCompressionDoesNotCount) {
  expect_at_onset(quadratic_delamination(stress(0, 0, 20, 0, 45, 25 * std::sqrt(2.0)), kS),
                  M::kDelamination, "delamination");
  const FailureIndex f = quadratic_delamination(stress(999, -99, 20, 77, 45, 25), kS);
  EXPECT_NEAR(f.criterion_value, 0.75, 1e-15);
  EXPECT_NEAR(f.index, std::sqrt(0.75), 1e-15);
  const FailureIndex c = quadratic_delamination(stress(0, 0, -100, 0, 54, 0), kS);
  EXPECT_NEAR(c.index, 0.6, 1e-15);
  EXPECT_EQ(quadratic_delamination(stress(500, 40, -300, 70, 0, 0), kS).mode, M::kNone);
}

TEST(FailureCriterion, DispatchMatchesTheCriteria) {
  const MaterialStress s = stress(-300, -60, 10, 30, 20, 15);
  EXPECT_EQ(evaluate_criterion(Criterion::kHashin, s, kS).index, hashin(s, kS).index);
  EXPECT_EQ(evaluate_criterion(Criterion::kTsaiWu, s, kS).index, tsai_wu(s, kS).index);
  EXPECT_EQ(evaluate_criterion(Criterion::kMaxStress, s, kS).index, max_stress(s, kS).index);
  EXPECT_EQ(evaluate_criterion(Criterion::kQuadraticDelamination, s, kS).index,
            quadratic_delamination(s, kS).index);
}

// A criterion that needs a strength the material lacks is refused naming the material and key.
TEST(CriterionStrengths, MissingStrengthNamesMaterialAndKey) {
  const Material bare = library_material("steel");
  try {
    strengths_for(Criterion::kHashin, bare);
    FAIL() << "accepted a material without strengths";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().key, "X_T");
    EXPECT_EQ(e.where().value, "steel");
    EXPECT_NE(std::string(e.what()).find("Hashin"), std::string::npos) << e.what();
  }
  PlyStrengths only_in_plane;
  for (StrengthKey k : {StrengthKey::kXT, StrengthKey::kXC, StrengthKey::kYT, StrengthKey::kYC,
                        StrengthKey::kS12, StrengthKey::kS23})
    only_in_plane.set(k, 100);
  const Material partial = library_material("paper-carbon-epoxy")
                               .with_failure_properties(only_in_plane, FractureToughness{})
                               .renamed("partial");
  EXPECT_NO_THROW(strengths_for(Criterion::kHashin, partial));
  try {
    strengths_for(Criterion::kQuadraticDelamination, partial);
    FAIL() << "accepted a material without Z_T";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().key, "Z_T");
    EXPECT_EQ(e.where().value, "partial");
  }
}

// Plate-axis stress to material axes: a 90 deg ply swaps 11 and 22 and 13 and 23 (with sign);
// a 45 deg ply under pure in-plane shear sees s11 = txy, s22 = -txy.
TEST(MaterialStress, RotationToPlyAxes) {
  Vector6d plate;
  plate << 100, 7, -20, 3, 5, -9;  // [11, 12, 22, 13, 23, 33]
  const MaterialStress r90 = to_material_axes(plate, 90);
  EXPECT_NEAR(r90.s11, -20, 1e-12);
  EXPECT_NEAR(r90.s22, 100, 1e-12);
  EXPECT_NEAR(r90.s12, -7, 1e-12);
  EXPECT_NEAR(r90.s13, 5, 1e-12);
  EXPECT_NEAR(r90.s23, -3, 1e-12);
  EXPECT_EQ(r90.s33, -9);
  Vector6d shear = Vector6d::Zero();
  shear(1) = 10;
  const MaterialStress r45 = to_material_axes(shear, 45);
  EXPECT_NEAR(r45.s11, 10, 1e-12);
  EXPECT_NEAR(r45.s22, -10, 1e-12);
  EXPECT_NEAR(r45.s12, 0, 1e-12);
}

}  // namespace
}  // namespace si
