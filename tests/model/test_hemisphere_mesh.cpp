#include "model/hemisphere_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "mesh_test_support.hpp"

namespace si {
namespace {

using testing::expect_set_is;

constexpr double kR = 10;  // MacNeal & Harder 1985 (linear.md)

TEST(HemisphereMesh, NodesOnTheSphereWithExactDirectorsAndSets) {
  const Mesh mesh = hemisphere_mesh(kR, 16);
  EXPECT_EQ(mesh.num_elements(), 256);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    ASSERT_NEAR(mesh.nodes[n].norm(), kR, 1e-12 * kR);
    ASSERT_LT((mesh.directors[n] - mesh.nodes[n] / kR).norm(), 1e-12);
  }
  for (int e = 0; e < mesh.num_elements(); ++e) {
    ASSERT_GT(element_normal(mesh, e).dot(testing::centroid(mesh, e)), 0) << "element " << e;
  }
  const double hole_z = kR * std::cos(18 * kPi / 180);  // 18 deg hole about the pole
  expect_set_is(mesh, "hole_edge",
                [&](const Vector3d& p) { return std::abs(p.z() - hole_z) < 1e-12; });
  expect_set_is(mesh, "equator", [](const Vector3d& p) { return p.z() == 0; });
  expect_set_is(mesh, "symmetry_x", [](const Vector3d& p) { return p.x() == 0; });
  expect_set_is(mesh, "symmetry_y", [](const Vector3d& p) { return p.y() == 0; });
  EXPECT_EQ(mesh.nodes[mesh.node_sets.at("load_x").at(0)], Vector3d(kR, 0, 0));
  EXPECT_EQ(mesh.nodes[mesh.node_sets.at("load_y").at(0)], Vector3d(0, kR, 0));
}

TEST(HemisphereMesh, AreaConvergesToTheZoneArea) {
  const double exact = 2 * kPi * kR * kR * std::cos(18 * kPi / 180) / 4;  // quarter of the zone
  const double coarse = mesh_area(hemisphere_mesh(kR, 8)) - exact;
  const double fine = mesh_area(hemisphere_mesh(kR, 16)) - exact;
  EXPECT_NEAR(testing::observed_order(coarse, fine), 2.0, 0.05);
  EXPECT_LT(std::abs(fine), 2e-3 * exact);
}

}  // namespace
}  // namespace si
