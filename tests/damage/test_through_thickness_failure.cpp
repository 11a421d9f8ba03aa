// The through-thickness evaluation (damage/through_thickness_failure.hpp): ply criteria at the
// bottom, middle and top of every ply, the interlaminar criterion at every interface in the axes of
// both plies that meet there (the larger counting), against the recovered stresses worked by hand;
// what it must not report, and what it refuses.
#include "damage/through_thickness_failure.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../section/laminate_fixtures.hpp"
#include "core/error.hpp"
#include "material/material_library.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

Laminate cross_ply() {
  return testing::make_laminate(library_material("im7-8552"), 0.5, {0, 90, 90, 0});
}

// A bending state with shear: M_x and M_y gradients and a top pressure.
PlateState shear_state(const VamSection& s) {
  PlateState state;
  const Matrix6d compliance = s.A_R.inverse();
  state.R = compliance * (Vector6d() << 0, 0, 0, 400, 0, -150).finished();
  state.dR[0] = compliance * (Vector6d() << 0, 0, 0, 300, 0, 0).finished();   // Q1 = 300 N/mm
  state.dR[1] = compliance * (Vector6d() << 0, 0, 0, 0, 0, -120).finished();  // Q2 = -120 N/mm
  state.t_top = -40;
  return state;
}

TEST(ThroughThicknessFailure, InterfacesUseTheLargerOfBothPliesAxes) {
  const Laminate laminate = cross_ply();
  const VamSection s = analyze_vam(laminate);
  const PlateState state = shear_state(s);
  const ThroughThicknessFailure failure(laminate, {Criterion::kQuadraticDelamination});
  const std::vector<RecoveredPoint> points = recover_through_thickness(s, state, 3);
  const CriterionFailure f = failure.evaluate(points)[0];
  ASSERT_EQ(f.points.size(), 3u);  // three interfaces
  const Strengths k = strengths_for(Criterion::kQuadraticDelamination, laminate.plies[0].material);
  double largest = 0;
  for (int i = 0; i < 3; ++i) {
    const RecoveredPoint& r = points[3 * (i + 1)];  // bottom of ply i + 1
    const double n = std::max(r.stress(5), 0.0) / k.Z_T;
    const double txz = r.stress(3), tyz = r.stress(4);
    // 0 deg axes: s13 = txz, s23 = tyz; 90 deg axes: s13 = tyz, s23 = -txz.
    const double zero = n * n + std::pow(txz / k.S_13, 2) + std::pow(tyz / k.S_23, 2);
    const double ninety = n * n + std::pow(tyz / k.S_13, 2) + std::pow(txz / k.S_23, 2);
    const double expected = std::sqrt(std::max(zero, ninety));
    EXPECT_NEAR(f.points[i].index.index, expected, 1e-12 * expected) << "interface " << i + 1;
    EXPECT_EQ(f.points[i].ply, i + 1);
    EXPECT_EQ(f.points[i].index.mode, FailureMode::kDelamination);
    largest = std::max(largest, expected);
  }
  EXPECT_NEAR(f.governing.index.index, largest, 1e-12 * largest);
  EXPECT_EQ(f.governing.ply, 2);  // the mid-plane interface carries the largest shear
}

TEST(ThroughThicknessFailure, PlyPointsAndTheirPositions) {
  const Laminate laminate = cross_ply();
  const VamSection s = analyze_vam(laminate);
  const ThroughThicknessFailure failure(laminate, {Criterion::kHashin, Criterion::kMaxStress});
  const std::vector<CriterionFailure> f =
      failure.evaluate(recover_through_thickness(s, shear_state(s), 3));
  ASSERT_EQ(f.size(), 2u);
  ASSERT_EQ(f[0].points.size(), 12u);
  EXPECT_EQ(f[0].criterion, Criterion::kHashin);
  EXPECT_EQ(f[0].points[4].ply, 1);
  EXPECT_EQ(f[0].points[4].position, PlyPosition::kMiddle);
  EXPECT_NEAR(f[0].points[11].x3, 1.0, 1e-15);
  // M_x > 0 bends the bottom 0 deg ply in tension along its fibre: bottom or top face governs.
  EXPECT_TRUE(f[1].governing.position != PlyPosition::kMiddle);
}

// Nothing loaded, nothing reported; a material without strengths is refused at construction; the
// recovered points must be the bottom, middle and top of each ply.
TEST(ThroughThicknessFailure, ReportsNothingUnloadedAndRefusesBadInput) {
  const Laminate laminate = cross_ply();
  const VamSection s = analyze_vam(laminate);
  const ThroughThicknessFailure failure(
      laminate, {Criterion::kTsaiWu, Criterion::kHashin, Criterion::kQuadraticDelamination});
  for (const CriterionFailure& c : failure.evaluate(recover_through_thickness(s, PlateState{}, 3)))
    for (const FailurePoint& p : c.points) {
      EXPECT_EQ(p.index.index, 0.0);
      EXPECT_EQ(p.index.mode, FailureMode::kNone);
    }
  EXPECT_THROW(failure.evaluate(recover_through_thickness(s, PlateState{}, 4)), Error);
  Laminate metal = testing::make_laminate(library_material("steel"), 1.0, {0});
  try {
    ThroughThicknessFailure(metal, {Criterion::kMaxStress});
    FAIL() << "accepted a material without strengths";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().value, "steel");
    EXPECT_EQ(e.where().key, "X_T");
  }
}

}  // namespace
}  // namespace si
