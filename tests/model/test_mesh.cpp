#include "model/mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/point_locator.hpp"
#include "model/structured_grid.hpp"

namespace si {
namespace {

// Two unit squares folded by `fold_deg` about the line x = 1 (a roof ridge).
Mesh folded_strip(double fold_deg) {
  const double a = fold_deg * 3.14159265358979323846 / 180;
  Mesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1 + std::cos(a), 0, -std::sin(a)},
                {0, 1, 0}, {1, 1, 0}, {1 + std::cos(a), 1, -std::sin(a)}};
  mesh.elements = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  return mesh;
}

TEST(Mesh, ElementAreaOfFlatQuadrilaterals) {
  Mesh mesh;
  mesh.nodes = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {3, 0, 0}, {2.5, 1, 0}};
  mesh.elements = {{0, 1, 2, 3}, {1, 4, 5, 2}};  // rectangle 2 x 1, trapezoid (1 + 0.5)/2
  EXPECT_DOUBLE_EQ(element_area(mesh, 0), 2.0);
  EXPECT_DOUBLE_EQ(element_area(mesh, 1), 0.75);
  EXPECT_DOUBLE_EQ(mesh_area(mesh), 2.75);
  EXPECT_TRUE(element_normal(mesh, 1).isApprox(Vector3d::UnitZ()));
}

TEST(Mesh, DirectorsFromElementsAverageAtARidge) {
  Mesh mesh = folded_strip(60);
  compute_directors_from_elements(mesh);
  const Vector3d n0 = Vector3d::UnitZ();
  const Vector3d n1(std::sin(3.14159265358979323846 / 3), 0, std::cos(3.14159265358979323846 / 3));
  EXPECT_TRUE(mesh.directors[0].isApprox(n0, 1e-14));
  EXPECT_TRUE(mesh.directors[2].isApprox(n1, 1e-14));
  // Equal areas: the ridge director bisects the two normals.
  EXPECT_TRUE(mesh.directors[1].isApprox((n0 + n1).normalized(), 1e-14));
  EXPECT_TRUE(mesh.directors[4].isApprox((n0 + n1).normalized(), 1e-14));
}

TEST(Mesh, FlipOrientationTurnsElementsAndDirectors) {
  Mesh mesh = folded_strip(0);
  compute_directors_from_elements(mesh);
  flip_orientation(mesh);
  EXPECT_TRUE(element_normal(mesh, 0).isApprox(-Vector3d::UnitZ()));
  EXPECT_TRUE(mesh.directors[3].isApprox(-Vector3d::UnitZ()));
  compute_directors_from_elements(mesh);
  EXPECT_TRUE(mesh.directors[3].isApprox(-Vector3d::UnitZ()));
}

TEST(Mesh, NodesWhereAndNodeSetsAreSortedAndUnique) {
  const Mesh mesh = folded_strip(30);
  EXPECT_EQ(nodes_where(mesh, [](const Vector3d& p) { return p.x() == 1; }),
            (std::vector<int>{1, 4}));
  Mesh copy = mesh;
  set_node_set(copy, "ridge", {4, 1, 4});
  EXPECT_EQ(copy.node_sets.at("ridge"), (std::vector<int>{1, 4}));
}

TEST(StructuredGrid, MergingBlocksSharesTheirBoundaryNodes) {
  Mesh mesh = structured_grid(2, 1, [](int i, int j) { return Vector3d(i, j, 0); });
  merge_into(mesh,
             structured_grid(1, 1, [](int i, int j) { return Vector3d(2 + i, j + 1e-12, 0); }),
             1e-9);
  EXPECT_EQ(mesh.num_nodes(), 8);  // 6 + 4 - 2 shared
  EXPECT_EQ(mesh.num_elements(), 3);
  EXPECT_EQ(mesh.elements[2][0], 2);  // (2, 0) is the first block's node 2
  EXPECT_EQ(mesh.elements[2][3], 5);  // (2, 1) its node 5
  EXPECT_DOUBLE_EQ(mesh_area(mesh), 3.0);
}

TEST(PointLocator, FindsOnlyPointsWithinTheTolerance) {
  PointLocator locator(0.1);
  locator.insert({1, 1, 1}, 7);
  locator.insert({1.05, 1, 1}, 3);
  EXPECT_EQ(locator.find({1.02, 1, 1}), 3);  // both within 0.1: the lowest index
  EXPECT_EQ(locator.find({0.95, 1, 1}), 7);
  EXPECT_EQ(locator.find({1.2, 1, 1}), -1);
  EXPECT_EQ(locator.find({-1, 1, 1}), -1);
}

}  // namespace
}  // namespace si
