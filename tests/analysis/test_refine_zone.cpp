// The refined zone sized from the indenter (analysis/refine_zone.hpp), against closed forms of
// the intersection of the undeformed indenter and contact face:
//  * a sphere on a plate: r = sqrt(2 R d - d^2);
//  * a sphere on the cap: the circle where two spheres meet, on their radical plane: with centre
//    distance D = (R - d) + rho, r^2 = R^2 - h^2, h = (D^2 + R^2 - rho^2) / (2 D);
//  * a flat punch: its radius (sharp), radius - e + sqrt(2 e d - d^2) with an edge radius e;
//  * an ellipsoid: a sqrt(1 - (1 - d/c)^2) along its longer plan axis; a cylinder: half its length;
// the zone is kept where the case sets it or imports its mesh, and is at least 4 elements wide;
// on the paper's cap the run's contact radius at depth_max lies inside it (the bound it rests on).
#include "analysis/refine_zone.hpp"

#include "analysis/indentation_run.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../indentation/indentation_test_support.hpp"

namespace si {
namespace {

IndentationCase plate_case(const IndenterSpec& indenter) {
  IndentationCase c = testing::coarse_cap_case("linear", "[0]8");
  c.shell.type = ShellType::kFlatCircularPlate;
  c.shell.radius = 50;
  c.indenter = indenter;
  return c;
}

IndenterSpec sphere(double radius) {
  IndenterSpec s;
  s.shape = IndenterShape::kSphere;
  s.radius = radius;
  return s;
}

TEST(RefineZone, SphereOnAPlateReachesTheChordOfItsCircle) {
  const IndentationCase c = plate_case(sphere(12.7));
  for (double d : {0.01, 0.5, 2.0, 10.0})
    EXPECT_NEAR(indenter_reach(c, d), std::sqrt(2 * 12.7 * d - d * d), 1e-9) << d;
  EXPECT_NEAR(indenter_reach(c, 20.0), 12.7, 1e-9);  // sunk past its equator: its own radius
  EXPECT_EQ(indenter_reach(c, 0.0), 0.0);
}

TEST(RefineZone, SphereOnTheCapMeetsItOnTheRadicalPlane) {
  IndentationCase c = testing::coarse_cap_case("nonlinear", "[0]8");
  const double R = 12.7, rho = 80.9 + 0.5 * c.laminate.thickness();  // outer face
  for (double d : {0.1, 2.0, 10.0}) {
    const double D = (R - d) + rho, h = (D * D + R * R - rho * rho) / (2 * D);
    EXPECT_NEAR(indenter_reach(c, d), std::sqrt(R * R - h * h), 1e-9) << d;
  }
  // The curved face falls away: less than on a plate.
  EXPECT_LT(indenter_reach(c, 2.0), std::sqrt(2 * R * 2.0 - 4.0));
}

TEST(RefineZone, FlatPunchEllipsoidAndCylinder) {
  IndenterSpec punch;
  punch.shape = IndenterShape::kFlatPunch;
  punch.radius = 5;
  EXPECT_NEAR(indenter_reach(plate_case(punch), 0.01), 5.0, 1e-9);
  punch.edge_radius = 1;
  EXPECT_NEAR(indenter_reach(plate_case(punch), 0.5), 4.0 + std::sqrt(2 * 0.5 - 0.25), 1e-9);
  EXPECT_NEAR(indenter_reach(plate_case(punch), 3.0), 5.0, 1e-9);

  IndenterSpec ellipsoid;
  ellipsoid.shape = IndenterShape::kSuperquadric;
  ellipsoid.a = 3;
  ellipsoid.b = 2;
  ellipsoid.c = 5;
  const double d = 1.5;
  EXPECT_NEAR(indenter_reach(plate_case(ellipsoid), d),
              3 * std::sqrt(1 - (1 - d / 5) * (1 - d / 5)), 1e-9);

  IndenterSpec cylinder;
  cylinder.shape = IndenterShape::kCylinder;
  cylinder.radius = 8;
  cylinder.length = 30;
  EXPECT_NEAR(indenter_reach(plate_case(cylinder), 0.2), 15.0, 1e-9);
}

TEST(RefineZone, SetOnlyWhereTheCaseLeavesItOpenAndAtLeastFourElements) {
  IndentationCase c = testing::coarse_cap_case("nonlinear", "[0]8", "quarter", 0.5, 2.0);
  EXPECT_EQ(with_refine_zone(c).mesh.refine_radius, 10.0);  // the case's own
  c.mesh.refine_radius.reset();
  c.path.depth_max = 2;
  EXPECT_NEAR(*with_refine_zone(c).mesh.refine_radius, indenter_reach(c, 2), 1e-12);
  c.path.depth_max = 1e-4;
  EXPECT_NEAR(*with_refine_zone(c).mesh.refine_radius, 4 * 0.5, 1e-12);
  c.mesh.file = "imported.msh";
  EXPECT_FALSE(with_refine_zone(c).mesh.refine_radius);
}

// The bound the zone rests on: the shell moves away from the indenter, so the contact stays
// where the undeformed bodies overlap. A coarse quarter cap to 2 mm.
TEST(RefineZone, ThePaperCapsContactStaysInsideIt) {
  CaseFile c = testing::coarse_cap_case("nonlinear", "[0]8", "quarter", 0.6, 2.0);
  c.mesh.refine_radius.reset();
  c.path.depth_max = 2;
  c.path.step = 0.25;
  IndentationSetup s(c, 1);
  const double zone = *s.spec.mesh.refine_radius;
  PathControl control;
  control.critical_points = false;
  const PathResult r = run_indentation_path(s, {}, control);
  ASSERT_TRUE(r.completed) << r.reason;
  const double contact = r.points.back().state.contact_radius;
  EXPECT_GT(contact, 0.2 * zone);  // not a vacuous bound
  EXPECT_LT(contact, zone);
}

}  // namespace
}  // namespace si
