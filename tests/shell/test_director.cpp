#include "shell/director.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

namespace si {
namespace {

// Bathe (1996) sec. 5.4: V1 = e2 x D / |e2 x D|, V2 = D x V1; V1 = e3 when D || e2.
TEST(Director, ReferenceFrameFollowsBathe) {
  const NodeState flat = reference_node_state(Vector3d::UnitZ());
  EXPECT_NEAR((flat.v1 - Vector3d::UnitX()).norm(), 0, 1e-15);
  EXPECT_NEAR((flat.v2 - Vector3d::UnitY()).norm(), 0, 1e-15);
  const NodeState up = reference_node_state(-Vector3d::UnitY());
  EXPECT_NEAR((up.v1 - Vector3d::UnitZ()).norm(), 0, 1e-15);
  EXPECT_NEAR((up.v2 - (-Vector3d::UnitY()).cross(Vector3d::UnitZ())).norm(), 0, 1e-15);
  const NodeState tilted = reference_node_state(Vector3d(0.3, 0.4, std::sqrt(0.75)));
  Matrix3d F;
  F << tilted.v1, tilted.v2, tilted.d;
  EXPECT_NEAR((F.transpose() * F - Matrix3d::Identity()).norm(), 0, 1e-15);
  EXPECT_NEAR(F.determinant(), 1, 1e-15);
}

TEST(Director, RejectsNonUnitDirector) {
  EXPECT_THROW(reference_node_state(Vector3d(0, 0, 2)), Error);
  EXPECT_THROW(reference_node_state(Vector3d::Zero()), Error);
}

// Rolling a cantilever into a full circle: 1000 increments about the (moving) v1 add up to
// 2 pi and bring the director back; a quarter turn about v1 takes d to -v2 (delta d = -a v2).
TEST(Director, MultiplicativeUpdateAccumulatesLargeRotations) {
  NodeState n = reference_node_state(Vector3d::UnitZ());
  const int steps = 1000;
  for (int k = 0; k < steps; ++k) rotate_node(n, 2 * M_PI / steps, 0);
  EXPECT_NEAR((n.d - Vector3d::UnitZ()).norm(), 0, 1e-12);
  EXPECT_NEAR((n.v1 - Vector3d::UnitX()).norm(), 0, 1e-12);
  NodeState q = reference_node_state(Vector3d::UnitZ());
  rotate_node(q, M_PI / 2, 0);
  EXPECT_NEAR((q.d - Vector3d(0, -1, 0)).norm(), 0, 1e-15);
  rotate_node(q, 0.7, -1.9);
  Matrix3d F;
  F << q.v1, q.v2, q.d;
  EXPECT_NEAR((F.transpose() * F - Matrix3d::Identity()).norm(), 0, 1e-14);
}

TEST(Director, RodriguesMatchesMatrixExponentialSeries) {
  for (double scale : {1e-9, 1e-5, 0.3, 3.0}) {
    const Vector3d theta = scale * Vector3d(0.2, -0.5, 0.8);
    Matrix3d S;
    S << 0, -theta.z(), theta.y(), theta.z(), 0, -theta.x(), -theta.y(), theta.x(), 0;
    Matrix3d series = Matrix3d::Identity(), term = Matrix3d::Identity();
    for (int k = 1; k < 40; ++k) {
      term = term * S / k;
      series += term;
    }
    EXPECT_NEAR((rotation_matrix(theta) - series).norm(), 0, 1e-14) << scale;
  }
}

}  // namespace
}  // namespace si
