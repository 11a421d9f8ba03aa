// Checks of the fake element the model-layer tests rely on (spring_net_element.hpp): its force is
// the derivative of its energy and its tangent the derivative of its force, both along the
// multiplicative rotation update of shell/director.hpp.
#include "spring_net_element.hpp"

#include <gtest/gtest.h>

namespace si {
namespace {

using Vec20 = Eigen::Matrix<double, 20, 1>;

std::array<NodeState, 4> perturbed(std::array<NodeState, 4> s, const Vec20& q) {
  for (int a = 0; a < 4; ++a) {
    s[a].u += q.segment<3>(5 * a);
    rotate_node(s[a], q[5 * a + 3], q[5 * a + 4]);
  }
  return s;
}

TEST(SpringNetElement, ForceAndTangentAreDerivatives) {
  ElementGeometry geo;
  geo.X = {Vector3d(0, 0, 0), Vector3d(1, 0, 0.1), Vector3d(1.1, 1, 0), Vector3d(0, 0.9, -0.1)};
  std::array<NodeState, 4> s;
  for (int a = 0; a < 4; ++a) {
    geo.D[a] = Vector3d(0.1 * a, -0.05, 1).normalized();
    s[a] = reference_node_state(geo.D[a]);
    s[a].u = Vector3d(0.1 * a, -0.05 * a * a, 0.2 - 0.1 * a);
    rotate_node(s[a], 0.2 - 0.1 * a, 0.1 * a);
  }
  const testing::SpringNetElement el;
  const ShellLaw law{};
  ElementResponse r0, rp, rm;
  el.compute(geo, s, law, Kinematics::kNonlinear, {}, r0);
  const double h = 1e-6;
  Eigen::Matrix<double, 20, 20> fd;
  Vec20 fe;
  for (int j = 0; j < 20; ++j) {
    Vec20 q = Vec20::Zero();
    q[j] = h;
    el.compute(geo, perturbed(s, q), law, Kinematics::kNonlinear, {}, rp);
    el.compute(geo, perturbed(s, -q), law, Kinematics::kNonlinear, {}, rm);
    fd.col(j) = (rp.force - rm.force) / (2 * h);
    fe[j] = (rp.energy - rm.energy) / (2 * h);
  }
  EXPECT_LT((fe - r0.force).norm() / r0.force.norm(), 1e-8);
  EXPECT_LT((fd - r0.tangent).norm() / r0.tangent.norm(), 1e-7);
  EXPECT_LT((r0.tangent - r0.tangent.transpose()).norm(), 1e-10 * r0.tangent.norm());
}

TEST(SpringNetElement, RigidTranslationCostsNothingAndLinearModeIsKq) {
  ElementGeometry geo;
  geo.X = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)};
  std::array<NodeState, 4> s;
  for (int a = 0; a < 4; ++a) {
    geo.D[a] = Vector3d::UnitZ();
    s[a] = reference_node_state(geo.D[a]);
    s[a].u = Vector3d(0.3, -0.2, 0.7);
  }
  const testing::SpringNetElement el;
  ElementResponse r;
  el.compute(geo, s, testing::unused_law(), Kinematics::kNonlinear, {}, r);
  EXPECT_LT(r.energy, 1e-25);
  EXPECT_LT(r.force.norm(), 1e-12);
  el.compute(geo, s, testing::unused_law(), Kinematics::kLinear, {}, r);
  EXPECT_LT(r.force.norm(), 1e-12);
  s[2].u.z() += 0.01;
  el.compute(geo, s, testing::unused_law(), Kinematics::kLinear, {}, r);
  Vec20 q = Vec20::Zero();
  for (int a = 0; a < 4; ++a) q.segment<3>(5 * a) = s[a].u;
  EXPECT_LT((r.force - r.tangent * q).norm(), 1e-12);
  EXPECT_GT(r.force.norm(), 1e-3);
}

}  // namespace
}  // namespace si
