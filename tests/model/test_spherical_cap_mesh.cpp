#include "model/spherical_cap_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/constants.hpp"
#include "mesh_test_support.hpp"
#include "model/mesh_quality.hpp"

namespace si {
namespace {

using testing::centroid;
using testing::expect_input_error;
using testing::longest_edge;
using testing::observed_order;

// Paper cap (paper-notes P8): c = 25 mm, R = 80.9 mm; exact area 2 pi R H.
double exact_area(const SphericalCapMeshSpec& spec) {
  return 2 * kPi * spec.sphere_radius * cap_height(spec);
}

SphericalCapMeshSpec uniform(double size, Symmetry symmetry = Symmetry::kFull) {
  SphericalCapMeshSpec spec;
  spec.size_apex = spec.size_edge = size;
  spec.refine_radius = 100;
  spec.symmetry = symmetry;
  return spec;
}

TEST(SphericalCapMesh, PaperCapIsValidAndReportsItsSize) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = spherical_cap_mesh({});
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "paper cap (size 0.5/2 mm, refine 13 mm, full): " << mesh.num_nodes() << " nodes, "
            << mesh.num_elements() << " elements, generated in " << ms << " ms\n";
  EXPECT_NO_THROW(check_mesh(mesh));
  EXPECT_NEAR(cap_height({}), 80.9 - std::sqrt(80.9 * 80.9 - 625), 1e-14);
  EXPECT_NEAR(mesh_area(mesh), exact_area({}), 1e-3 * exact_area({}));
}

TEST(SphericalCapMesh, NodesOnTheSphereWithExactOutwardDirectors) {
  for (auto symmetry : {Symmetry::kFull, Symmetry::kQuarter}) {
    SphericalCapMeshSpec spec;
    spec.symmetry = symmetry;
    const Mesh mesh = spherical_cap_mesh(spec);
    const Vector3d centre(0, 0, cap_height(spec) - spec.sphere_radius);
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const Vector3d radial = mesh.nodes[n] - centre;
      ASSERT_NEAR(radial.norm(), spec.sphere_radius, 1e-12 * spec.sphere_radius) << "node " << n;
      ASSERT_LT((mesh.directors[n] - radial / spec.sphere_radius).norm(), 1e-12) << "node " << n;
      ASSERT_GE(mesh.nodes[n].z(), -1e-12);
    }
    // Counter-clockwise seen from outside: element normals point away from the centre.
    for (int e = 0; e < mesh.num_elements(); ++e) {
      ASSERT_GT(element_normal(mesh, e).dot(centroid(mesh, e) - centre), 0) << "element " << e;
    }
  }
}

TEST(SphericalCapMesh, EdgeAndApexNodeSets) {
  const SphericalCapMeshSpec spec;
  const Mesh mesh = spherical_cap_mesh(spec);
  testing::expect_set_is(mesh, "edge", [&](const Vector3d& p) {
    return std::abs(std::hypot(p.x(), p.y()) - spec.base_radius) < 1e-9;
  });
  for (int n : mesh.node_sets.at("edge")) EXPECT_NEAR(mesh.nodes[n].z(), 0, 1e-12);
  ASSERT_EQ(mesh.node_sets.at("apex").size(), 1u);
  EXPECT_TRUE(mesh.nodes[mesh.node_sets.at("apex")[0]].isApprox(Vector3d(0, 0, cap_height(spec))));
  EXPECT_EQ(mesh.node_sets.count("symmetry_x"), 0u);  // only the quarter model has them
}

TEST(SphericalCapMesh, GradedSizesNearTheApexAndTheEdge) {
  const SphericalCapMeshSpec spec;  // 0.5 mm within 13 mm, 2 mm at the edge
  const Mesh mesh = spherical_cap_mesh(spec);
  const auto& edge = mesh.node_sets.at("edge");
  const auto on_edge = [&](int n) { return std::binary_search(edge.begin(), edge.end(), n); };
  double apex_max = 0, edge_max = 0, edge_sum = 0;
  int edge_count = 0;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const Vector3d c = centroid(mesh, e);
    const double arc =
        spec.sphere_radius * std::asin(std::hypot(c.x(), c.y()) / spec.sphere_radius);
    const double h = longest_edge(mesh, e);
    if (arc < spec.refine_radius - 0.5) apex_max = std::max(apex_max, h);
    const auto& el = mesh.elements[e];
    if (std::any_of(el.begin(), el.end(), on_edge)) {  // the outermost ring
      edge_max = std::max(edge_max, h);
      edge_sum += h;
      ++edge_count;
    }
  }
  EXPECT_LE(apex_max, 1.5 * spec.size_apex);
  EXPECT_LE(edge_max, 1.5 * spec.size_edge);
  EXPECT_GT(edge_sum / edge_count, 0.75 * spec.size_edge);  // coarse where asked, not uniform
}

TEST(SphericalCapMesh, RadialSpacingGrowsSmoothly) {
  SphericalCapMeshSpec spec;
  spec.symmetry = Symmetry::kQuarter;
  const Mesh mesh = spherical_cap_mesh(spec);
  // Stations along the symmetry line y = 0, from the apex to the edge.
  std::vector<double> x;
  for (int n : mesh.node_sets.at("symmetry_y")) x.push_back(mesh.nodes[n].x());
  std::sort(x.begin(), x.end());
  for (size_t k = 2; k < x.size(); ++k) {
    const double ratio = (x[k] - x[k - 1]) / (x[k - 1] - x[k - 2]);
    EXPECT_LT(ratio, 1.25) << "at x = " << x[k];
    EXPECT_GT(ratio, 0.8) << "at x = " << x[k];
  }
}

TEST(SphericalCapMesh, AreaConvergesAtSecondOrder) {
  const double exact = exact_area(uniform(1));
  const double coarse = mesh_area(spherical_cap_mesh(uniform(2))) - exact;
  const double fine = mesh_area(spherical_cap_mesh(uniform(1))) - exact;
  EXPECT_NEAR(observed_order(coarse, fine), 2.0, 0.2);
  EXPECT_LT(std::abs(fine), 1e-3 * exact);
}

TEST(SphericalCapMesh, QuarterModelIsAQuarterWithSymmetrySets) {
  SphericalCapMeshSpec spec;
  const double full = mesh_area(spherical_cap_mesh(spec));
  spec.symmetry = Symmetry::kQuarter;
  const Mesh quarter = spherical_cap_mesh(spec);
  EXPECT_NEAR(4 * mesh_area(quarter), full, 1e-10 * full);
  testing::expect_set_is(quarter, "symmetry_x", [](const Vector3d& p) { return p.x() == 0; });
  testing::expect_set_is(quarter, "symmetry_y", [](const Vector3d& p) { return p.y() == 0; });
  EXPECT_EQ(quarter.node_sets.at("symmetry_x").size(), quarter.node_sets.at("symmetry_y").size());
  for (const Vector3d& p : quarter.nodes) EXPECT_TRUE(p.x() >= 0 && p.y() >= 0);
  const int apex = quarter.node_sets.at("apex").at(0);
  EXPECT_TRUE(std::binary_search(quarter.node_sets.at("symmetry_x").begin(),
                                 quarter.node_sets.at("symmetry_x").end(), apex));
}

TEST(SphericalCapMesh, RejectsImpossibleGeometryNamingTheField) {
  SphericalCapMeshSpec spec;
  spec.base_radius = 90;
  expect_input_error([&] { spherical_cap_mesh(spec); }, {"base_radius", "smaller than the sphere"});
  spec = {};
  spec.size_apex = 0;
  expect_input_error([&] { spherical_cap_mesh(spec); }, {"size_apex"});
  spec = {};
  spec.size_apex = 3;
  expect_input_error([&] { spherical_cap_mesh(spec); }, {"size_apex", "must not exceed size_edge"});
  spec = {};
  spec.refine_radius = -1;
  expect_input_error([&] { spherical_cap_mesh(spec); }, {"refine_radius"});
}

}  // namespace
}  // namespace si
