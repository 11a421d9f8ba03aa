#include "model/plate_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "mesh_test_support.hpp"
#include "model/mesh_quality.hpp"

namespace si {
namespace {

using testing::expect_input_error;
using testing::expect_set_is;
using testing::observed_order;

TEST(RectangularPlateMesh, AreaEdgesAndCentre) {
  const Mesh mesh = rectangular_plate_mesh(10, 1, 16, 2);  // Sze cantilever strip, 16 x 1 doubled
  EXPECT_EQ(mesh.num_nodes(), 17 * 3);
  EXPECT_EQ(mesh.num_elements(), 32);
  EXPECT_NEAR(mesh_area(mesh), 10.0, 1e-12);
  expect_set_is(mesh, "edge_x0", [](const Vector3d& p) { return p.x() == 0; });
  expect_set_is(mesh, "edge_x1", [](const Vector3d& p) { return p.x() == 10; });
  expect_set_is(mesh, "edge_y0", [](const Vector3d& p) { return p.y() == 0; });
  expect_set_is(mesh, "edge_y1", [](const Vector3d& p) { return p.y() == 1; });
  expect_set_is(mesh, "edge", [](const Vector3d& p) {
    return p.x() == 0 || p.x() == 10 || p.y() == 0 || p.y() == 1;
  });
  ASSERT_EQ(mesh.node_sets.at("center").size(), 1u);
  EXPECT_TRUE(mesh.nodes[mesh.node_sets.at("center")[0]].isApprox(Vector3d(5, 0.5, 0)));
  for (const Vector3d& d : mesh.directors) EXPECT_EQ(d, Vector3d::UnitZ());
  EXPECT_EQ(rectangular_plate_mesh(10, 1, 16, 1).node_sets.count("center"), 0u);
}

TEST(RectangularPlateMesh, RejectsBadSizes) {
  expect_input_error([] { rectangular_plate_mesh(-1, 1, 2, 2); }, {"lx"});
  expect_input_error([] { rectangular_plate_mesh(1, 1, 2, 0); }, {"ny"});
}

TEST(CircularPlateMesh, AreaConvergesAtSecondOrderWithEdgeAndCentre) {
  const double exact = kPi * 25 * 25;
  const Mesh coarse = circular_plate_mesh(25, 2, 2, 25, Symmetry::kFull);
  const Mesh fine = circular_plate_mesh(25, 1, 1, 25, Symmetry::kFull);
  EXPECT_NEAR(observed_order(mesh_area(coarse) - exact, mesh_area(fine) - exact), 2.0, 0.2);
  expect_set_is(fine, "edge", [](const Vector3d& p) { return std::abs(p.norm() - 25) < 1e-9; });
  expect_set_is(fine, "center", [](const Vector3d& p) { return p.norm() == 0; });
  for (const Vector3d& p : fine.nodes) EXPECT_EQ(p.z(), 0);
}

TEST(CircularPlateMesh, GradedQuarterModel) {
  const Mesh full = circular_plate_mesh(25, 0.5, 2, 13, Symmetry::kFull);
  const Mesh quarter = circular_plate_mesh(25, 0.5, 2, 13, Symmetry::kQuarter);
  EXPECT_NEAR(4 * mesh_area(quarter), mesh_area(full), 1e-10 * mesh_area(full));
  expect_set_is(quarter, "symmetry_x", [](const Vector3d& p) { return p.x() == 0; });
  expect_set_is(quarter, "symmetry_y", [](const Vector3d& p) { return p.y() == 0; });
  expect_set_is(quarter, "center", [](const Vector3d& p) { return p.norm() == 0; });
  // Every edge node of the full disk has a counterpart in the quarter's four rotations.
  EXPECT_EQ(full.node_sets.at("edge").size(), 4 * (quarter.node_sets.at("edge").size() - 1));
}

TEST(CircularPlateMesh, VeryCoarseEdgeSizeGivesMoreRingsNotElongatedElements) {
  const Mesh mesh = circular_plate_mesh(25, 0.5, 10, 13, Symmetry::kQuarter);
  for (int e = 0; e < mesh.num_elements(); ++e) {
    ASSERT_LT(element_quality(mesh, e).aspect_ratio, 5) << "element " << e;
  }
}

TEST(CircularPlateMesh, RejectsACoarserCentreThanEdge) {
  expect_input_error([] { circular_plate_mesh(25, 2, 1, 13, Symmetry::kFull); },
                     {"size_center", "must not exceed"});
}

TEST(MacNealHarderPatchMesh, NodesOfLinearMdAndFiveValidElements) {
  const Mesh mesh = macneal_harder_patch_mesh();
  ASSERT_EQ(mesh.num_nodes(), 8);
  EXPECT_EQ(mesh.num_elements(), 5);
  // MacNeal & Harder 1985 (linear.md, patch tests): interior nodes.
  EXPECT_EQ(mesh.nodes[4], Vector3d(0.04, 0.02, 0));
  EXPECT_EQ(mesh.nodes[5], Vector3d(0.18, 0.03, 0));
  EXPECT_EQ(mesh.nodes[6], Vector3d(0.16, 0.08, 0));
  EXPECT_EQ(mesh.nodes[7], Vector3d(0.08, 0.08, 0));
  EXPECT_NEAR(mesh_area(mesh), 0.24 * 0.12, 1e-15);
  expect_set_is(mesh, "boundary", [](const Vector3d& p) {
    return p.x() == 0 || p.y() == 0 || p.x() == 0.24 || p.y() == 0.12;
  });
  EXPECT_EQ(mesh.node_sets.at("interior"), (std::vector<int>{4, 5, 6, 7}));
  for (int e = 0; e < mesh.num_elements(); ++e) {
    EXPECT_GT(element_normal(mesh, e).z(), 0.99) << "element " << e;
    EXPECT_LT(element_quality(mesh, e).min_scaled_jacobian, 0.9) << "patch must be distorted";
  }
}

TEST(AnnulusWithSlitMesh, LipsAreSeparateCoincidentNodeSets) {
  const Mesh mesh = annulus_with_slit_mesh(6, 10, 10, 80);  // Sze et al. 2004 reference mesh
  EXPECT_EQ(mesh.num_elements(), 800);
  EXPECT_EQ(mesh.num_nodes(), 11 * 81);
  const auto& fixed = mesh.node_sets.at("slit_fixed");
  const auto& loaded = mesh.node_sets.at("slit_loaded");
  ASSERT_EQ(fixed.size(), 11u);
  ASSERT_EQ(loaded.size(), 11u);
  for (size_t k = 0; k < fixed.size(); ++k) {
    EXPECT_NE(fixed[k], loaded[k]);
    EXPECT_EQ(mesh.nodes[fixed[k]], mesh.nodes[loaded[k]]);
    EXPECT_EQ(mesh.nodes[fixed[k]].y(), 0);
  }
  // The loaded lip belongs to elements below the slit (y < 0), the fixed one to those above.
  for (int e = 0; e < mesh.num_elements(); ++e) {
    for (int n : mesh.elements[e]) {
      if (std::binary_search(loaded.begin(), loaded.end(), n)) {
        EXPECT_LT(testing::centroid(mesh, e).y(), 0);
      }
      if (std::binary_search(fixed.begin(), fixed.end(), n)) {
        EXPECT_GT(testing::centroid(mesh, e).y(), 0);
      }
    }
  }
  EXPECT_EQ(mesh.nodes[mesh.node_sets.at("loaded_inner").at(0)], Vector3d(6, 0, 0));
  EXPECT_EQ(mesh.nodes[mesh.node_sets.at("loaded_outer").at(0)], Vector3d(10, 0, 0));
  expect_set_is(mesh, "inner_edge",
                [](const Vector3d& p) { return std::abs(p.norm() - 6) < 1e-12; });
  expect_set_is(mesh, "outer_edge",
                [](const Vector3d& p) { return std::abs(p.norm() - 10) < 1e-12; });
  // The default checks refuse the intended crack; the generator validates with it allowed.
  expect_input_error([&] { check_mesh(mesh); }, {"coincide"});
}

TEST(AnnulusWithSlitMesh, AreaConvergesAtSecondOrder) {
  const double exact = kPi * (10 * 10 - 6 * 6);
  const double coarse = mesh_area(annulus_with_slit_mesh(6, 10, 4, 32)) - exact;
  const double fine = mesh_area(annulus_with_slit_mesh(6, 10, 8, 64)) - exact;
  EXPECT_NEAR(observed_order(coarse, fine), 2.0, 0.05);
  expect_input_error([] { annulus_with_slit_mesh(6, 5, 4, 32); }, {"outer_r"});
}

}  // namespace
}  // namespace si
