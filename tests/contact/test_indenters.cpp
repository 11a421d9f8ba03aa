// Properties every indenter shape must have (exact for the closed-form shapes), checked at many
// points: unit outward normal = gradient of the distance, its derivative = the returned Hessian
// (finite differences, 1e-6), the implicit function's sign, rigid travel.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "contact/cylinder_indenter.hpp"
#include "contact/flat_punch_indenter.hpp"
#include "contact/sphere_indenter.hpp"
#include "contact/superquadric_indenter.hpp"
#include "indenter_test_support.hpp"

namespace si {
namespace {

struct Case {
  std::shared_ptr<Indenter> indenter;
  bool exact_distance;  // false: first-order distance (super-quadric)
  // Points to skip: on the kinks of the derivative (region boundaries, axes).
  std::function<bool(const Vector3d&)> skip;
};

IndenterPose tilted_pose() {
  IndenterPose pose;
  pose.position = Vector3d(0.3, -0.2, 5.0);
  pose.direction = Vector3d(0.1, 0.2, -1.0).normalized();
  return pose;
}

std::vector<Case> cases() {
  const IndenterPose pose = tilted_pose();
  const Vector3d& d = pose.direction;
  // Flat punch R = 4, r_e = 1: skip points near the face plane, the core radius and the axis.
  auto punch_kinks = [pose, d](const Vector3d& x) {
    const Vector3d v = x - (pose.position - 1.0 * d);
    const double s = v.dot(d), rho = (v - s * d).norm();
    return std::abs(s) < 0.05 || std::abs(rho - 3.0) < 0.05 || std::abs(rho - 3.0 - s) < 0.05 ||
           rho < 0.05;
  };
  auto centre_far = [pose](const Vector3d& x) { return (x - pose.position).norm() < 0.1; };
  auto q = std::make_shared<SuperquadricIndenter>(SuperquadricShape{3.0, 4.0, 2.5, 0.5, 0.8}, pose);
  auto cyl = std::make_shared<CylinderIndenter>(2.0, 0.0, pose);
  auto capsule = std::make_shared<CylinderIndenter>(2.0, 3.0, pose);
  auto near_axis = [pose, c = capsule](const Vector3d& x) {
    const Vector3d v = x - pose.position;
    const double s = v.dot(c->axis());
    return (v - s * c->axis()).norm() < 0.1 || std::abs(std::abs(s) - 1.5) < 0.05;
  };
  return {{std::make_shared<SphereIndenter>(3.0, pose), true, centre_far},
          {std::make_shared<FlatPunchIndenter>(4.0, 1.0, pose), true, punch_kinks},
          {cyl, true, near_axis},
          {capsule, true, near_axis},
          {q, false, centre_far}};
}

const std::vector<Vector3d>& cloud() {
  static const std::vector<Vector3d> points =
      test::box_points(Vector3d(-6, -6, -2), Vector3d(6, 6, 10), 9);
  return points;
}

TEST(Indenters, NormalIsUnitAndAlongTheImplicitGradient_Eq32) {
  for (const Case& c : cases()) {
    const Indenter& ind = *c.indenter;
    int checked = 0;
    for (const Vector3d& x : cloud()) {
      if (c.skip(x)) continue;
      Vector3d n;
      ind.signed_distance(x, 0.7, &n, nullptr);
      EXPECT_NEAR(n.norm(), 1.0, 1e-12) << ind.name();
      // Paper eq 32: n = grad f / |grad f|.
      const Vector3d gf =
          test::fd_gradient([&](const Vector3d& y) { return ind.implicit(y, 0.7); }, x);
      EXPECT_LT((n - gf.normalized()).norm(), 1e-6) << ind.name() << " at " << x.transpose();
      ++checked;
    }
    EXPECT_GT(checked, 500) << ind.name();
  }
}

TEST(Indenters, NormalIsTheDistanceGradientForExactDistances) {
  for (const Case& c : cases()) {
    if (!c.exact_distance) continue;
    const Indenter& ind = *c.indenter;
    for (const Vector3d& x : cloud()) {
      if (c.skip(x)) continue;
      Vector3d n;
      ind.signed_distance(x, 0.7, &n, nullptr);
      const Vector3d g = test::fd_gradient(
          [&](const Vector3d& y) { return ind.signed_distance(y, 0.7, nullptr, nullptr); }, x);
      EXPECT_LT((n - g).norm(), 1e-6) << ind.name() << " at " << x.transpose();
    }
  }
}

TEST(Indenters, HessianIsTheNormalDerivative) {
  for (const Case& c : cases()) {
    const Indenter& ind = *c.indenter;
    for (const Vector3d& x : cloud()) {
      if (c.skip(x)) continue;
      Matrix3d h;
      ind.signed_distance(x, 0.7, nullptr, &h);
      const Matrix3d fd = test::fd_normal_jacobian(ind, x, 0.7);
      EXPECT_LT((h - fd).norm(), 1e-6 * (1.0 + h.norm())) << ind.name() << " at " << x.transpose();
    }
  }
}

TEST(Indenters, ImplicitHasTheSignOfTheDistance) {
  for (const Case& c : cases()) {
    const Indenter& ind = *c.indenter;
    for (const Vector3d& x : cloud()) {
      const double sd = ind.signed_distance(x, 0.7, nullptr, nullptr);
      const double f = ind.implicit(x, 0.7);
      if (std::abs(sd) < 1e-9) continue;
      EXPECT_EQ(sd > 0, f > 0) << ind.name() << " at " << x.transpose();
    }
  }
}

TEST(Indenters, NormalPointsOutward) {
  for (const Case& c : cases()) {
    const Indenter& ind = *c.indenter;
    for (const Vector3d& x : cloud()) {
      if (c.skip(x)) continue;
      Vector3d n;
      const double sd = ind.signed_distance(x, 0.7, &n, nullptr);
      EXPECT_GT(ind.signed_distance(x + 1e-4 * n, 0.7, nullptr, nullptr), sd) << ind.name();
    }
  }
}

TEST(Indenters, TravelMovesTheSurfaceRigidly) {
  const Vector3d d = tilted_pose().direction;
  for (const Case& c : cases()) {
    const Indenter& ind = *c.indenter;
    for (const Vector3d& x : cloud()) {
      Vector3d n1, n0;
      Matrix3d h1, h0;
      const double s1 = ind.signed_distance(x, 1.3, &n1, &h1);
      const double s0 = ind.signed_distance(x - 1.3 * d, 0.0, &n0, &h0);
      EXPECT_NEAR(s1, s0, 1e-12) << ind.name();
      EXPECT_LT((n1 - n0).norm(), 1e-9) << ind.name();
      EXPECT_LT((h1 - h0).norm(), 1e-9 * (1.0 + h0.norm())) << ind.name();
    }
  }
}

}  // namespace
}  // namespace si
