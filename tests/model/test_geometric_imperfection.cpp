// add_imperfection (model/geometric_imperfection.hpp) against the exact surface: a flat plate
// given the bump w = a sin(pi x / L) sin(pi y / L) moves each node by w exactly, and its directors
// become the normals of z = w(x, y), (-w_x, -w_y, 1) / |...|, to the area-weighted average's
// second order in the element size. What must not happen: a zero imperfection changing anything.
#include "model/geometric_imperfection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/constants.hpp"
#include "mesh_test_support.hpp"
#include "model/plate_meshes.hpp"
#include "model/supports.hpp"

namespace si {
namespace {

using testing::observed_order;

constexpr double kL = 100.0;   // mm
constexpr double kBump = 0.5;  // mm: slopes up to pi a / L = 0.016

double bump(const Vector3d& p) {
  return kBump * std::sin(kPi * p.x() / kL) * std::sin(kPi * p.y() / kL);
}

Vector3d exact_normal(const Vector3d& p) {
  const double c = kBump * kPi / kL;
  const double wx = c * std::cos(kPi * p.x() / kL) * std::sin(kPi * p.y() / kL);
  const double wy = c * std::sin(kPi * p.x() / kL) * std::cos(kPi * p.y() / kL);
  return Vector3d(-wx, -wy, 1.0).normalized();
}

// The largest angle (rad) between a director and the bumped surface's normal, and the largest
// position error, after adding the bump to an n x n plate.
struct Errors {
  double angle = 0, interior_angle = 0, position = 0;
};
Errors bumped_plate_errors(int n) {
  Mesh mesh = rectangular_plate_mesh(kL, kL, n, n);
  const Mesh flat = mesh;
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(mesh.num_nodes(), 3);
  for (int i = 0; i < mesh.num_nodes(); ++i) t(i, 2) = bump(mesh.nodes[i]);
  add_imperfection(mesh, t);
  Errors e;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Vector3d expected = flat.nodes[i] + Vector3d(0, 0, bump(flat.nodes[i]));
    e.position = std::max(e.position, (mesh.nodes[i] - expected).norm());
    EXPECT_NEAR(mesh.directors[i].norm(), 1.0, 1e-14);
    const double cos = std::clamp(mesh.directors[i].dot(exact_normal(flat.nodes[i])), -1.0, 1.0);
    e.angle = std::max(e.angle, std::acos(cos));
    const Vector3d& p = flat.nodes[i];
    if (p.x() > 0 && p.x() < kL && p.y() > 0 && p.y() < kL)
      e.interior_angle = std::max(e.interior_angle, std::acos(cos));
  }
  return e;
}

TEST(GeometricImperfection, BumpedPlateDirectorsAreTheSurfaceNormalsToSecondOrder) {
  const Errors coarse = bumped_plate_errors(16), fine = bumped_plate_errors(32);
  EXPECT_EQ(coarse.position, 0.0);
  EXPECT_EQ(fine.position, 0.0);
  // Inside, the area-weighted average of the four element normals is the surface normal to
  // second order; on the edges the one-sided average is first order.
  EXPECT_GT(observed_order(coarse.interior_angle, fine.interior_angle), 1.8)
      << coarse.interior_angle << " " << fine.interior_angle;
  EXPECT_GT(observed_order(coarse.angle, fine.angle), 0.9) << coarse.angle << " " << fine.angle;
  EXPECT_LT(fine.interior_angle, 0.01 * kPi * kBump / kL);  // against slopes of 0.016 rad
}

TEST(GeometricImperfection, ZeroImperfectionChangesNothing) {
  Mesh mesh = rectangular_plate_mesh(kL, 0.5 * kL, 8, 4);
  const Mesh before = mesh;
  add_imperfection(mesh, Eigen::MatrixXd::Zero(mesh.num_nodes(), 3));
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    EXPECT_EQ(mesh.nodes[i], before.nodes[i]);
    EXPECT_EQ(mesh.directors[i], before.directors[i]);
  }
}

TEST(GeometricImperfection, OneTranslationPerNodeRequired) {
  Mesh mesh = rectangular_plate_mesh(kL, kL, 4, 4);
  EXPECT_THROW(add_imperfection(mesh, Eigen::MatrixXd::Zero(mesh.num_nodes() - 1, 3)),
               std::invalid_argument);
  EXPECT_THROW(add_imperfection(mesh, Eigen::MatrixXd::Zero(mesh.num_nodes(), 2)),
               std::invalid_argument);
}

// A quarter model: the plate [0, L]^2 is the quarter x, y >= 0 of [-L, L]^2, bumped by the
// symmetric w = a cos(pi x / 2L) cos(pi y / 2L), whose exact normal lies in the planes x = 0 and
// y = 0 there. add_imperfection's one-sided element normals tilt the plane nodes' directors out of
// their planes (which the symmetry supports refuse); keep_directors_in_symmetry_planes puts them
// back, closer to the exact normal than before, and touches no other node.
TEST(GeometricImperfection, SymmetryPlaneDirectorsStayInTheirPlanes) {
  Mesh mesh = rectangular_plate_mesh(kL, kL, 8, 8);
  std::vector<int>& on_x = mesh.node_sets["symmetry_x"];
  std::vector<int>& on_y = mesh.node_sets["symmetry_y"];
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    if (mesh.nodes[i].x() == 0.0) on_x.push_back(i);
    if (mesh.nodes[i].y() == 0.0) on_y.push_back(i);
  }
  ASSERT_EQ(on_x.size(), 9u);
  const double k = kPi / (2 * kL);
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(mesh.num_nodes(), 3);
  for (int i = 0; i < mesh.num_nodes(); ++i)
    t(i, 2) = kBump * std::cos(k * mesh.nodes[i].x()) * std::cos(k * mesh.nodes[i].y());
  const auto exact = [&](const Vector3d& p) {
    return Vector3d(kBump * k * std::sin(k * p.x()) * std::cos(k * p.y()),
                    kBump * k * std::cos(k * p.x()) * std::sin(k * p.y()), 1.0)
        .normalized();
  };
  add_imperfection(mesh, t);
  const Mesh tilted = mesh;
  double off_plane = 0;
  for (int n : on_x) off_plane = std::max(off_plane, std::abs(tilted.directors[n].x()));
  EXPECT_GT(off_plane, 1e-4);  // the defect this mends: a director off its plane
  const std::vector<Support> planes = {{SupportKind::kSymmetryPlane, "symmetry_x", 0, {}},
                                       {SupportKind::kSymmetryPlane, "symmetry_y", 1, {}},
                                       {SupportKind::kClamped, "symmetry_x", -1, {}}};
  keep_directors_in_symmetry_planes(mesh, planes);
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Vector3d& p = tilted.nodes[i];
    const bool x0 = p.x() == 0.0, y0 = p.y() == 0.0;
    if (!x0 && !y0) {
      EXPECT_EQ(mesh.directors[i], tilted.directors[i]);
      continue;
    }
    if (x0) {
      EXPECT_EQ(mesh.directors[i].x(), 0.0);
    }
    if (y0) {
      EXPECT_EQ(mesh.directors[i].y(), 0.0);
    }
    EXPECT_NEAR(mesh.directors[i].norm(), 1.0, 1e-14);
    EXPECT_GE(mesh.directors[i].dot(exact(p)), tilted.directors[i].dot(exact(p)) - 1e-15);
  }
}

}  // namespace
}  // namespace si
