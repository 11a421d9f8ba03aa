#include "shell/director.hpp"

#include <cmath>

#include "core/error.hpp"

namespace si {

NodeState reference_node_state(const Vector3d& D) {
  const double norm = D.norm();
  SI_REQUIRE(std::isfinite(norm) && std::abs(norm - 1) < 1e-6,
             "shell director must be a unit vector (|D| = " + std::to_string(norm) + ")");
  NodeState node;
  node.d = D / norm;
  const Vector3d e2_x_d = Vector3d::UnitY().cross(node.d);
  node.v1 = e2_x_d.norm() < 1e-8 ? Vector3d::UnitZ() : Vector3d(e2_x_d.normalized());
  node.v2 = node.d.cross(node.v1);
  return node;
}

Matrix3d rotation_matrix(const Vector3d& theta) {
  const double angle = theta.norm();
  Matrix3d S;
  S << 0, -theta.z(), theta.y(), theta.z(), 0, -theta.x(), -theta.y(), theta.x(), 0;
  // sin(x)/x and (1 - cos(x))/x^2 by their Taylor series near 0 to avoid cancellation.
  const double a = angle < 1e-4 ? 1 - angle * angle / 6 : std::sin(angle) / angle;
  const double b =
      angle < 1e-4 ? 0.5 - angle * angle / 24 : (1 - std::cos(angle)) / (angle * angle);
  return Matrix3d::Identity() + a * S + b * S * S;
}

void rotate_node(NodeState& node, double a, double b) {
  const Matrix3d Q = rotation_matrix(a * node.v1 + b * node.v2);
  node.d = Q * node.d;
  node.v1 = Q * node.v1;
  // Re-orthonormalise so that round-off does not accumulate over thousands of updates.
  node.d.normalize();
  node.v1 = (node.v1 - node.v1.dot(node.d) * node.d).normalized();
  node.v2 = node.d.cross(node.v1);
}

}  // namespace si
