#include "model/cylindrical_panel_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "mesh_test_support.hpp"

namespace si {
namespace {

using testing::expect_input_error;
using testing::expect_set_is;
using testing::observed_order;

// Scordelis-Lo roof (linear.md): R = 25, L = 50, half-angle 40 deg.
constexpr double kR = 25, kL = 50, kHalfDeg = 40;
const double kHalf = kHalfDeg * kPi / 180;

TEST(CylindricalPanelMesh, ScordelisLoFullPanelGeometryAndDirectors) {
  const Mesh mesh = cylindrical_panel_mesh(kR, kL, kHalfDeg, 16, 16);
  EXPECT_EQ(mesh.num_elements(), 256);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vector3d& p = mesh.nodes[n];
    ASSERT_NEAR(std::hypot(p.x(), p.z()), kR, 1e-12 * kR);
    ASSERT_LT((mesh.directors[n] - Vector3d(p.x(), 0, p.z()) / kR).norm(), 1e-12);
    ASSERT_LE(std::abs(p.y()), kL / 2);
  }
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const Vector3d c = testing::centroid(mesh, e);
    ASSERT_GT(element_normal(mesh, e).dot(Vector3d(c.x(), 0, c.z())), 0)
        << "outward, element " << e;
  }
  const double edge_x = kR * std::sin(kHalf);
  expect_set_is(mesh, "curved_ends", [](const Vector3d& p) { return std::abs(p.y()) == kL / 2; });
  expect_set_is(mesh, "straight_edges",
                [&](const Vector3d& p) { return std::abs(std::abs(p.x()) - edge_x) < 1e-12; });
  expect_set_is(mesh, "axial_midplane", [](const Vector3d& p) { return p.y() == 0; });
  expect_set_is(mesh, "crown", [](const Vector3d& p) { return p.x() == 0; });
  EXPECT_EQ(mesh.nodes[mesh.node_sets.at("center").at(0)], Vector3d(0, 0, kR));
  EXPECT_TRUE(mesh.nodes[mesh.node_sets.at("free_edge_mid").at(0)].isApprox(
      Vector3d(edge_x, 0, kR * std::cos(kHalf)), 1e-14));
}

TEST(CylindricalPanelMesh, AreaConvergesAndQuarterIsAQuarter) {
  const double exact = kR * 2 * kHalf * kL;
  const double coarse = mesh_area(cylindrical_panel_mesh(kR, kL, kHalfDeg, 4, 4)) - exact;
  const double fine = mesh_area(cylindrical_panel_mesh(kR, kL, kHalfDeg, 8, 8)) - exact;
  EXPECT_NEAR(observed_order(coarse, fine), 2.0, 0.05);
  const Mesh quarter = cylindrical_panel_mesh(kR, kL, kHalfDeg, 4, 4, PanelPart::kQuarter);
  EXPECT_NEAR(4 * mesh_area(quarter), fine + exact, 1e-10 * exact);  // 4 x 4 = 8 x 8 / 4
  expect_set_is(quarter, "curved_ends", [](const Vector3d& p) { return p.y() == kL / 2; });
  expect_set_is(quarter, "axial_midplane", [](const Vector3d& p) { return p.y() == 0; });
  expect_set_is(quarter, "crown", [](const Vector3d& p) { return p.x() == 0; });
  EXPECT_EQ(quarter.node_sets.at("straight_edges").size(), 5u);
  for (const Vector3d& p : quarter.nodes) EXPECT_TRUE(p.x() >= 0 && p.y() >= 0);
}

TEST(CylindricalPanelMesh, SzeHingedRoof) {
  // Sze et al. 2004, 3.8: R = 2540, axial length 508, half-angle 0.1 rad.
  const Mesh mesh = cylindrical_panel_mesh(2540, 508, 0.1 * 180 / kPi, 8, 8);
  EXPECT_EQ(mesh.nodes[mesh.node_sets.at("center").at(0)], Vector3d(0, 0, 2540));
  for (int n : mesh.node_sets.at("straight_edges")) {
    EXPECT_NEAR(std::abs(mesh.nodes[n].x()), 2540 * std::sin(0.1), 1e-9);
  }
}

TEST(CylindricalPanelMesh, PinchedCylinderOctant) {
  const Mesh mesh = pinched_cylinder_octant_mesh(300, 600, 16, 16);  // linear.md
  EXPECT_EQ(mesh.nodes[mesh.node_sets.at("load").at(0)], Vector3d(0, 0, 300));
  expect_set_is(mesh, "diaphragm", [](const Vector3d& p) { return p.y() == 300; });
  expect_set_is(mesh, "symmetry_x", [](const Vector3d& p) { return p.x() == 0; });
  expect_set_is(mesh, "symmetry_y", [](const Vector3d& p) { return p.y() == 0; });
  expect_set_is(mesh, "symmetry_z", [](const Vector3d& p) { return p.z() == 0; });
  EXPECT_NEAR(mesh_area(mesh), 300 * kPi / 2 * 300, 1e-2 * 300 * kPi / 2 * 300);
}

TEST(CylindricalPanelMesh, RejectsOddDivisionsOfTheFullPanel) {
  expect_input_error([] { cylindrical_panel_mesh(kR, kL, kHalfDeg, 3, 4); }, {"n_axial", "even"});
  expect_input_error([] { cylindrical_panel_mesh(kR, kL, 200, 4, 4); }, {"half_angle_deg"});
  EXPECT_NO_THROW(cylindrical_panel_mesh(kR, kL, kHalfDeg, 3, 5, PanelPart::kQuarter));
}

}  // namespace
}  // namespace si
