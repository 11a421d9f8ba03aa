#include "contact/travel_gap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "contact/indenter_factory.hpp"
#include "indenter_test_support.hpp"

namespace si {
namespace {

IndenterPose pose_above() {
  IndenterPose pose;
  pose.position = Vector3d(0.3, -0.2, 20.0);
  pose.direction = Vector3d(0.1, 0.05, -1.0).normalized();
  return pose;
}

std::unique_ptr<Indenter> indenter(IndenterShape shape) {
  IndenterSpec spec;
  spec.shape = shape;
  spec.radius = 6.0;
  spec.edge_radius = 1.5;
  spec.length = 30.0;
  spec.a = 5.0, spec.b = 7.0, spec.c = 4.0, spec.e1 = 0.8, spec.e2 = 0.9;
  return make_indenter(spec, pose_above());
}

// Sphere: s(p) = (p - c0).e - sqrt(R^2 - |(p - c0) x e|^2), the entry root of |p - c0 - s e| = R.
TEST(TravelGap, SphereClosedForm) {
  const auto ind = indenter(IndenterShape::kSphere);
  const IndenterPose pose = pose_above();
  const Vector3d p(1.2, 0.4, 0.7);
  const Vector3d q = p - pose.position;
  const double expected =
      q.dot(pose.direction) - std::sqrt(36.0 - q.cross(pose.direction).squaredNorm());
  const TravelGap g = travel_gap(*ind, pose.direction, p, 0.0, true);
  ASSERT_TRUE(g.hits);
  EXPECT_NEAR(g.travel, expected, 1e-12);
  EXPECT_NEAR(g.gradient.dot(pose.direction), 1.0, 1e-14);
}

// ds/dp and d2s/dp2 against central differences of s, for every shape.
TEST(TravelGap, DerivativesMatchFiniteDifferences) {
  for (IndenterShape shape : {IndenterShape::kSphere, IndenterShape::kSuperquadric,
                              IndenterShape::kFlatPunch, IndenterShape::kCylinder}) {
    const auto ind = indenter(shape);
    const Vector3d e = pose_above().direction;
    // Points under the indenter, off its axis (on the punch's edge rounding for the punch).
    for (const Vector3d& p :
         {Vector3d(1.1, 0.6, 0.5), Vector3d(-2.0, 1.0, -0.3), Vector3d(4.6, 0.2, 0.1)}) {
      const TravelGap g = travel_gap(*ind, e, p, 0.0, true);
      ASSERT_TRUE(g.hits) << ind->name();
      const auto s = [&](const Vector3d& x) {
        return travel_gap(*ind, e, x, g.travel, false).travel;
      };
      const double h = 1e-5;
      EXPECT_LT((g.gradient - test::fd_gradient(s, p, h)).norm(), 1e-8 * g.gradient.norm())
          << ind->name();
      Matrix3d fd;
      for (int j = 0; j < 3; ++j) {
        Vector3d dx = Vector3d::Zero();
        dx(j) = h;
        fd.col(j) = (travel_gap(*ind, e, p + dx, g.travel, false).gradient -
                     travel_gap(*ind, e, p - dx, g.travel, false).gradient) /
                    (2 * h);
      }
      EXPECT_LT((g.hessian - fd).cwiseAbs().maxCoeff(), 1e-6 * (1 + g.hessian.norm()))
          << ind->name() << " at " << p.transpose();
    }
  }
}

TEST(TravelGap, PointBesideThePathIsNotHit) {
  const auto ind = indenter(IndenterShape::kSphere);
  const TravelGap g = travel_gap(*ind, pose_above().direction, Vector3d(9.0, 0.0, 0.0), 0.0, true);
  EXPECT_FALSE(g.hits);
}

}  // namespace
}  // namespace si
