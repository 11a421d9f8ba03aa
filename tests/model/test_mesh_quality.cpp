#include "model/mesh_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh_test_support.hpp"

namespace si {
namespace {

using testing::expect_input_error;

// Two unit squares side by side in z = 0, counter-clockwise about +z:
//   3---4---5
//   | 0 | 1 |
//   0---1---2
Mesh two_squares() {
  Mesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  mesh.directors.assign(6, Vector3d::UnitZ());
  mesh.elements = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  return mesh;
}

Mesh single(std::vector<Vector3d> corners) {
  Mesh mesh;
  mesh.nodes = std::move(corners);
  mesh.directors.assign(4, Vector3d::UnitZ());
  mesh.elements = {{0, 1, 2, 3}};
  return mesh;
}

TEST(MeshQuality, AcceptsAGoodMeshAndMeasuresASquare) {
  const Mesh mesh = two_squares();
  EXPECT_NO_THROW(check_mesh(mesh));
  const ElementQuality q = element_quality(mesh, 1);
  EXPECT_DOUBLE_EQ(q.area, 1.0);
  EXPECT_DOUBLE_EQ(q.min_scaled_jacobian, 1.0);
  EXPECT_DOUBLE_EQ(q.aspect_ratio, 1.0);
  EXPECT_DOUBLE_EQ(q.warp_deg, 0.0);
  EXPECT_DOUBLE_EQ(q.max_director_angle_deg, 0.0);
}

TEST(MeshQuality, RejectsAnInvertedElement) {
  Mesh mesh = two_squares();
  mesh.elements[1] = {1, 4, 5, 2};  // clockwise about the directors
  expect_input_error([&] { check_mesh(mesh); }, {"element 1 (nodes 1 4 5 2)", "inverted"});
}

TEST(MeshQuality, RejectsARepeatedNode) {
  Mesh mesh = two_squares();
  mesh.elements[1] = {1, 2, 2, 4};
  expect_input_error([&] { check_mesh(mesh); }, {"element 1 (nodes 1 2 2 4)", "repeats node 2"});
}

TEST(MeshQuality, RejectsZeroArea) {
  const Mesh mesh = single({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
  expect_input_error([&] { check_mesh(mesh); }, {"element 0 (nodes 0 1 2 3)", "zero area"});
}

TEST(MeshQuality, RejectsAMissingNode) {
  Mesh mesh = two_squares();
  mesh.elements[1][2] = 9;
  expect_input_error([&] { check_mesh(mesh); },
                     {"element 1 (nodes 1 2 9 4)", "references node 9", "6 nodes"});
  mesh.elements[1][2] = -1;
  expect_input_error([&] { check_mesh(mesh); }, {"element 1", "references node -1"});
}

TEST(MeshQuality, RejectsUnmergedDuplicateNodes) {
  Mesh mesh = two_squares();
  mesh.nodes.push_back(mesh.nodes[4]);  // node 6 duplicates node 4 ...
  mesh.directors.push_back(Vector3d::UnitZ());
  mesh.elements[1][3] = 6;  // ... and element 1 uses it: a crack along x = 1
  expect_input_error([&] { check_mesh(mesh); }, {"nodes 4 and 6 coincide", "not merged"});
  MeshQualityLimits allow;
  allow.allow_coincident_nodes = true;
  EXPECT_NO_THROW(check_mesh(mesh, allow));
}

TEST(MeshQuality, RejectsAnUnusedNode) {
  Mesh mesh = two_squares();
  mesh.nodes.push_back({5, 5, 0});
  mesh.directors.push_back(Vector3d::UnitZ());
  expect_input_error([&] { check_mesh(mesh); }, {"node 6 is not used"});
}

TEST(MeshQuality, RejectsBadDirectors) {
  Mesh mesh = two_squares();
  mesh.directors[5] = Vector3d(0, 0, 2);
  expect_input_error([&] { check_mesh(mesh); }, {"director of node 5", "not a unit vector"});
  mesh.directors[5] = Vector3d(std::sin(1.0), 0, std::cos(1.0));  // 57 deg off the normal
  expect_input_error([&] { check_mesh(mesh); }, {"element 1 (nodes 1 2 5 4)", "director"});
  mesh.directors.pop_back();
  expect_input_error([&] { check_mesh(mesh); }, {"6 nodes but 5 directors"});
}

TEST(MeshQuality, RejectsDistortedElongatedAndWarpedElements) {
  // Corner of 178.9 deg at node 1.
  expect_input_error(
      [] {
        check_mesh(single({{0, 0, 0}, {1, -0.01, 0}, {2, 0, 0}, {1, 1, 0}}));
      },
      {"element 0", "scaled Jacobian"});
  // Corner of 181.1 deg: not convex, the Jacobian changes sign.
  expect_input_error(
      [] {
        check_mesh(single({{0, 0, 0}, {1, 0.01, 0}, {2, 0, 0}, {1, 1, 0}}));
      },
      {"element 0", "inverted or folded"});
  expect_input_error(
      [] {
        check_mesh(single({{0, 0, 0}, {100, 0, 0}, {100, 1, 0}, {0, 1, 0}}));
      },
      {"element 0", "aspect ratio 100"});
  // Strongly tapered: the corner Jacobians differ by a factor 33, no corner angle is small.
  const Mesh tapered = single({{0, 0, 0}, {10, 0, 0}, {5.15, 1, 0}, {4.85, 1, 0}});
  EXPECT_NEAR(element_quality(tapered, 0).jacobian_ratio, 0.03, 1e-12);
  EXPECT_GT(element_quality(tapered, 0).min_scaled_jacobian, 0.05);
  expect_input_error([&] { check_mesh(tapered); }, {"element 0", "Jacobian ratio 0.03"});
  // One corner lifted by the edge length: the two triangle halves meet at 60 deg.
  const Mesh warped = single({{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}});
  EXPECT_NEAR(element_quality(warped, 0).warp_deg, 60, 1e-12);
  expect_input_error([&] { check_mesh(warped); }, {"element 0", "warp angle 60"});
  MeshQualityLimits lenient;
  lenient.max_warp_deg = 61;
  EXPECT_NO_THROW(check_mesh(warped, lenient));
}

TEST(MeshQuality, RejectsInconsistentOrientationNamingBothElements) {
  Mesh mesh = two_squares();
  mesh.elements[1] = {1, 4, 5, 2};
  expect_input_error([&] { check_orientation_consistency(mesh); },
                     {"element 1 (nodes 1 4 5 2)", "element 0 (nodes 0 1 4 3)", "inconsistent"});
}

TEST(MeshQuality, RejectsBadNodeSets) {
  Mesh mesh = two_squares();
  mesh.node_sets["edge"] = {0, 7};
  expect_input_error([&] { check_mesh(mesh); }, {"node set 'edge'", "node 7"});
  mesh.node_sets["edge"] = {3, 0};
  expect_input_error([&] { check_mesh(mesh); }, {"node set 'edge'", "sorted"});
}

}  // namespace
}  // namespace si
