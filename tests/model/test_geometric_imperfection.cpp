// add_imperfection (model/geometric_imperfection.hpp) against the exact surface: a flat plate
// given the bump w = a sin(pi x / L) sin(pi y / L) moves each node by w exactly, and its directors
// become the normals of z = w(x, y), (-w_x, -w_y, 1) / |...|, to the area-weighted average's
// second order in the element size. What must not happen: a zero imperfection changing anything.
#include "model/geometric_imperfection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"
#include "mesh_test_support.hpp"
#include "model/plate_meshes.hpp"

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

}  // namespace
}  // namespace si
