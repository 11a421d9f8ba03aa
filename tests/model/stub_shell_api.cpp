// Minimal implementations of the shell-element API declared in src/shell/ and src/model/mesh.hpp
// (written by other engineers in parallel), so that the model layer can be tested alone. At merge
// the real implementations replace this file.
#include <Eigen/Geometry>

#include "model/mesh.hpp"
#include "shell/director.hpp"

namespace si {

int Mesh::num_nodes() const {
  return static_cast<int>(nodes.size());
}
int Mesh::num_elements() const {
  return static_cast<int>(elements.size());
}

NodeState reference_node_state(const Vector3d& D) {
  NodeState s;
  s.u.setZero();
  s.d = D;
  const Vector3d e2 = Vector3d::UnitY();
  const Vector3d c = e2.cross(D);
  s.v1 = c.norm() < 1e-12 ? Vector3d(Vector3d::UnitZ()) : Vector3d(c.normalized());
  s.v2 = D.cross(s.v1);
  return s;
}

void rotate_node(NodeState& s, double a, double b) {
  const Vector3d w = a * s.v1 + b * s.v2;
  const double angle = w.norm();
  if (angle == 0.0) return;
  const Matrix3d R = Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
  s.d = R * s.d;
  s.v1 = R * s.v1;
  s.v2 = R * s.v2;
}

}  // namespace si
