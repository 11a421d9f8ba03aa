// First touch (Indenter::first_touch) against closed forms: each indenter over a flat plate of
// points and a sphere over a spherical cloud of points.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/cylinder_indenter.hpp"
#include "contact/flat_punch_indenter.hpp"
#include "contact/sphere_indenter.hpp"
#include "contact/superquadric_indenter.hpp"
#include "core/error.hpp"
#include "indenter_test_support.hpp"

namespace si {
namespace {

constexpr double kTol = 1e-9;
const double kPlateZ = -0.7;

// Directly above a plate point (the grid step is 1), so the closed forms hold for the points.
IndenterPose above(double z) {
  IndenterPose pose;
  pose.position = Vector3d(1.0, -2.0, z);
  return pose;
}

const std::vector<Vector3d>& plate() {
  static const std::vector<Vector3d> points = test::plate_points(10.0, kPlateZ, 21);
  return points;
}

// A sphere centred at height z0 + h touches the plate z = z0 at travel h - R.
TEST(FirstTouch, SphereOverPlate) {
  const SphereIndenter sphere(3.0, above(6.0));
  EXPECT_NEAR(sphere.first_touch(plate()), 6.0 - 3.0 - kPlateZ, kTol);
}

TEST(FirstTouch, FlatPunchOverPlate) {
  const FlatPunchIndenter punch(4.0, 0.5, above(2.0));  // the flat face is at the position
  EXPECT_NEAR(punch.first_touch(plate()), 2.0 - kPlateZ, kTol);
}

TEST(FirstTouch, CylinderOverPlate) {
  const CylinderIndenter cylinder(1.5, 6.0, above(4.0));
  EXPECT_NEAR(cylinder.first_touch(plate()), 4.0 - 1.5 - kPlateZ, kTol);
}

// The ellipsoid's first-order distance over-estimates the gap off its axes: the bisection path.
TEST(FirstTouch, EllipsoidOverPlate) {
  const SuperquadricIndenter ellipsoid(SuperquadricShape{5.0, 3.0, 2.0, 1.0, 1.0}, above(4.0));
  EXPECT_NEAR(ellipsoid.first_touch(plate()), 4.0 - 2.0 - kPlateZ, kTol);
}

// Sphere R above a spherical cap of points (radius Rs, centre at the origin, pole included):
// touch at travel H - R - Rs, the pole being first.
TEST(FirstTouch, SphereOverSphereOfPoints) {
  const double rs = 20.0;
  std::vector<Vector3d> points{Vector3d(0, 0, rs)};
  for (int i = 1; i <= 10; ++i)
    for (int j = 0; j < 16; ++j) {
      const double polar = 0.05 * i, azimuth = 2 * M_PI * j / 16;
      points.emplace_back(rs * std::sin(polar) * std::cos(azimuth),
                          rs * std::sin(polar) * std::sin(azimuth), rs * std::cos(polar));
    }
  IndenterPose pose;
  pose.position = Vector3d(0, 0, 30.0);
  const SphereIndenter sphere(4.0, pose);
  EXPECT_NEAR(sphere.first_touch(points), 30.0 - 4.0 - rs, kTol);
}

TEST(FirstTouch, StartingInsideGivesANegativeTravel) {
  const SphereIndenter sphere(3.0, above(1.0));  // already 1.7 mm into the plate
  EXPECT_NEAR(sphere.first_touch(plate()), 1.0 - 3.0 - kPlateZ, kTol);
}

TEST(FirstTouch, MovingAwayOrEmptyIsAnInputError) {
  IndenterPose away = above(6.0);
  away.direction = Vector3d(0, 0, 1);
  const SphereIndenter sphere(3.0, away);
  try {
    sphere.first_touch(plate());
    FAIL() << "expected an input error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
  }
  EXPECT_THROW(sphere.first_touch({}), Error);
}

}  // namespace
}  // namespace si
