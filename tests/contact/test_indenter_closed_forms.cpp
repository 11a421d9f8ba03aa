// Signed distances against closed forms evaluated independently here, and the super-quadric's
// reductions to a sphere (a = b = c, e1 = e2 = 1: paper eq 29) and to a near-flat punch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/cylinder_indenter.hpp"
#include "contact/flat_punch_indenter.hpp"
#include "contact/sphere_indenter.hpp"
#include "contact/superquadric_indenter.hpp"
#include "indenter_test_support.hpp"

namespace si {
namespace {

const std::vector<Vector3d>& cloud() {
  static const std::vector<Vector3d> points =
      test::box_points(Vector3d(-7, -7, -4), Vector3d(7, 7, 9), 11);
  return points;
}

IndenterPose pose_at(const Vector3d& position) {
  IndenterPose pose;
  pose.position = position;
  return pose;
}

TEST(IndenterClosedForms, SphereDistanceIsCentreDistanceMinusRadius) {
  const Vector3d c(0.5, -0.3, 2.0);
  const SphereIndenter sphere(3.0, pose_at(c));
  for (const Vector3d& x : cloud()) {
    const Vector3d moved_centre = c + 0.8 * Vector3d(0, 0, -1);
    EXPECT_NEAR(sphere.signed_distance(x, 0.8, nullptr, nullptr), (x - moved_centre).norm() - 3.0,
                1e-12);
  }
}

// Minkowski sum of the core {s <= 0, rho <= R - r_e} and a ball r_e: outside, the distance to
// the core (projection by clamping s and rho) minus r_e; inside, by hand at chosen points.
TEST(IndenterClosedForms, FlatPunchDistanceIsTheMinkowskiSumDistance) {
  const double radius = 4.0, edge = 1.0;
  const Vector3d tip(0.2, 0.1, 3.0);
  const FlatPunchIndenter punch(radius, edge, pose_at(tip));
  const Vector3d core_centre = tip + Vector3d(0, 0, edge);  // r_e behind the face (travel -z)
  int outside = 0;
  for (const Vector3d& x : cloud()) {
    const double height = x.z() - core_centre.z();  // the body extends towards +z
    const double s = -height;                       // axial coordinate along the travel
    const double rho = (x - core_centre).head<2>().norm();
    const double ds = std::max(s, 0.0), dr = std::max(rho - (radius - edge), 0.0);
    const double to_core = std::hypot(ds, dr);
    if (to_core == 0.0) continue;
    EXPECT_NEAR(punch.signed_distance(x, 0.0, nullptr, nullptr), to_core - edge, 1e-12)
        << x.transpose();
    ++outside;
  }
  EXPECT_GT(outside, 600);
  // Inside: nearer the face (depth 0.5 behind it) and nearer the side wall (0.25 from it).
  EXPECT_NEAR(punch.signed_distance(tip + Vector3d(0, 0, 0.5), 0.0, nullptr, nullptr), -0.5, 1e-12);
  EXPECT_NEAR(punch.signed_distance(tip + Vector3d(3.75, 0, 5.0), 0.0, nullptr, nullptr), -0.25,
              1e-12);
}

TEST(IndenterClosedForms, CylinderDistanceIsAxisDistanceMinusRadius) {
  const Vector3d c(0.0, 0.0, 2.5);
  const CylinderIndenter infinite(1.5, 0.0, pose_at(c));  // axis x2 by default
  const CylinderIndenter capsule(1.5, 4.0, pose_at(c));
  for (const Vector3d& x : cloud()) {
    const Vector3d v = x - c;
    const double to_axis = std::hypot(v.x(), v.z());
    EXPECT_NEAR(infinite.signed_distance(x, 0.0, nullptr, nullptr), to_axis - 1.5, 1e-12);
    const double beyond = std::max(std::abs(v.y()) - 2.0, 0.0);  // past the straight part
    EXPECT_NEAR(capsule.signed_distance(x, 0.0, nullptr, nullptr),
                std::hypot(to_axis, beyond) - 1.5, 1e-12);
  }
}

// Paper eq 29: the super-quadric with a = b = c = R and unit exponents is the sphere; its
// first-order distance is then exact (docs/theory/indenters.md).
TEST(IndenterClosedForms, SuperquadricWithEqualAxesAndUnitExponentsIsTheSphere_Eq29) {
  IndenterPose pose = pose_at(Vector3d(0.3, 0.2, 1.0));
  pose.direction = Vector3d(0.2, 0.0, -1.0).normalized();
  const SphereIndenter sphere(2.5, pose);
  const SuperquadricIndenter quadric(SuperquadricShape{2.5, 2.5, 2.5, 1.0, 1.0}, pose);
  for (const Vector3d& x : cloud()) {
    Vector3d ns, nq;
    Matrix3d hs, hq;
    const double ds = sphere.signed_distance(x, 0.4, &ns, &hs);
    const double dq = quadric.signed_distance(x, 0.4, &nq, &hq);
    EXPECT_NEAR(dq, ds, 1e-12);
    EXPECT_LT((nq - ns).norm(), 1e-12);
    EXPECT_LT((hq - hs).norm(), 1e-12);
    EXPECT_NEAR(quadric.implicit(x, 0.4), sphere.implicit(x, 0.4), 1e-12);
  }
}

// Small e1 (a large exponent 2/e1 = 20 on x3) with a round cross-section (e2 = 1) is a cylinder
// with near-flat ends. In front of the lower face, within half the radius and up to 0.1 c away,
// the radial function is g = (rho/a)^20 + w^20)^(1/20) - 1 with w = |Z|/c, so the first-order
// distance differs from the plane distance |Z| - c by about (rho/(a w))^20 w c / 20
// <= 0.5^20 c / 20 = 4.8e-8 c; the normal is -x3 to the same order.
TEST(IndenterClosedForms, SuperquadricWithLargeExponentIsANearFlatPunch) {
  const double a = 4.0, c = 2.0;
  const Vector3d centre(0.0, 0.0, 5.0);
  const SuperquadricIndenter quadric(SuperquadricShape{a, a, c, 0.1, 1.0}, pose_at(centre));
  int checked = 0;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
      for (int k = 1; k <= 5; ++k) {
        const Vector3d x =
            centre + Vector3d(0.2 * a * (i - 5) / 5.0, 0.2 * a * (j - 5) / 5.0, -c - 0.02 * c * k);
        if ((x - centre).head<2>().norm() > 0.5 * a) continue;
        Vector3d n;
        const double gap = centre.z() - c - x.z();
        EXPECT_NEAR(quadric.signed_distance(x, 0.0, &n, nullptr), gap, 1e-7 * c);
        EXPECT_LT((n - Vector3d(0, 0, -1)).norm(), 1e-6);
        ++checked;
      }
  EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace si
