#include "model/twisted_beam_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "mesh_test_support.hpp"

namespace si {
namespace {

// Area of the helicoid (x, w cos a, w sin a), |w| <= b, a' = k: L (b sqrt(1 + k^2 b^2) +
// asinh(k b) / k).
double helicoid_area(double length, double half_width, double k) {
  return length * (half_width * std::sqrt(1 + k * k * half_width * half_width) +
                   std::asinh(k * half_width) / k);
}

TEST(TwistedBeamMesh, MacNealHarderStandardMesh) {
  const Mesh mesh = twisted_beam_mesh();  // 12 x 2 (linear.md)
  EXPECT_EQ(mesh.num_elements(), 24);
  EXPECT_EQ(mesh.num_nodes(), 39);
  const double k = kPi / 2 / 12;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vector3d& p = mesh.nodes[n];
    const double a = k * p.x();
    // On the helicoid: the point lies on the generator at angle a, within the half-width.
    ASSERT_NEAR(p.y() * std::sin(a) - p.z() * std::cos(a), 0, 1e-14);
    ASSERT_LE(std::hypot(p.y(), p.z()), 0.55 + 1e-14);
    const double w = p.y() * std::cos(a) + p.z() * std::sin(a);
    const Vector3d normal = Vector3d(-w * k, -std::sin(a), std::cos(a)).normalized();
    ASSERT_LT((mesh.directors[n] - normal).norm(), 1e-14);
  }
  ASSERT_EQ(mesh.node_sets.at("root").size(), 3u);
  ASSERT_EQ(mesh.node_sets.at("tip").size(), 3u);
  for (int n : mesh.node_sets.at("root")) {
    EXPECT_EQ(mesh.nodes[n].x(), 0);
    EXPECT_EQ(mesh.nodes[n].z(), 0);  // width along y at the root
  }
  for (int n : mesh.node_sets.at("tip")) {
    EXPECT_EQ(mesh.nodes[n].x(), 12);
    EXPECT_NEAR(mesh.nodes[n].y(), 0, 1e-15);  // width along z at the tip
  }
}

TEST(TwistedBeamMesh, AreaConvergesAtSecondOrder) {
  const double exact = helicoid_area(12, 0.55, kPi / 2 / 12);
  TwistedBeamSpec spec;
  spec.n_length = 12;
  spec.n_width = 2;
  const double coarse = mesh_area(twisted_beam_mesh(spec)) - exact;
  spec.n_length = 24;
  spec.n_width = 4;
  const double fine = mesh_area(twisted_beam_mesh(spec)) - exact;
  EXPECT_NEAR(testing::observed_order(coarse, fine), 2.0, 0.05);
}

}  // namespace
}  // namespace si
