#include "contact/node_gap.hpp"

#include "contact/travel_gap.hpp"

namespace si {
namespace {

Eigen::Matrix<double, 3, 2> director_map(const NodeState& s) {
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = -s.v2;
  E.col(1) = s.v1;
  return E;
}

Vector5d gap_gradient(const Vector3d& a, const Eigen::Matrix<double, 3, 2>& E, double c) {
  Vector5d G;
  G.head<3>() = a;
  G.tail<2>() = c * E.transpose() * a;
  return G;
}

// The gradient of a gap whose rate in the contact point is a (and its Hessian A), and its
// derivative under an increment (the header's dG).
void set_gradient(const Vector3d& a, const Matrix3d& A, const NodeState& state, double c,
                  bool want_derivative, NodeGap& out) {
  const Eigen::Matrix<double, 3, 2> E = director_map(state);
  out.gradient = gap_gradient(a, E, c);
  if (!want_derivative) return;
  const Vector3d m = state.d.cross(a);
  const Vector3d v[2] = {state.v1, state.v2};
  Matrix2d N;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) N(i, j) = v[j].dot(v[i].cross(m)) + E.col(j).dot(a.cross(v[i]));
  Matrix5d& dG = out.gradient_derivative;
  dG.topLeftCorner<3, 3>() = A;
  dG.topRightCorner<3, 2>() = c * A * E;
  dG.bottomLeftCorner<2, 3>() = c * E.transpose() * A;
  dG.bottomRightCorner<2, 2>() = c * c * E.transpose() * A * E + c * N;
}

}  // namespace

NodeGap node_gap(const Indenter& indenter, const Vector3d& direction,
                 const NodeContactGeometry& node, const NodeState& state, double travel,
                 double guess, bool want_derivative) {
  NodeGap out;
  const Vector3d p = node.X + state.u + node.offset * state.d;
  const TravelGap tg = travel_gap(indenter, direction, p, guess, want_derivative);
  if (!tg.hits) return out;
  out.hits = true;
  out.touch_travel = tg.travel;
  out.gap = tg.travel - travel;
  set_gradient(tg.gradient, want_derivative ? tg.hessian : Matrix3d::Zero(), state, node.offset,
               want_derivative, out);
  return out;
}

NodeGap plane_gap(const Vector3d& normal, double level, const NodeContactGeometry& node,
                  const NodeState& state, bool want_derivative) {
  NodeGap out;
  out.hits = true;
  out.gap = normal.dot(node.X + state.u + node.offset * state.d) - level;
  set_gradient(normal, Matrix3d::Zero(), state, node.offset, want_derivative, out);
  return out;
}

NodeGap linearized_plane_gap(const Vector3d& normal, double level, const NodeContactGeometry& node,
                             const NodeState& reference, const Vector5d& coordinates) {
  NodeGap out = plane_gap(normal, level, node, reference, false);
  out.gap += out.gradient.dot(coordinates);
  return out;
}

NodeGap linearized_node_gap(const Indenter& indenter, const Vector3d& direction,
                            const NodeContactGeometry& node, const NodeState& reference,
                            const Vector5d& coordinates, double travel) {
  NodeGap out;
  const Vector3d P = node.X + node.offset * reference.d;
  const TravelGap tg = travel_gap(indenter, direction, P, travel, false);
  if (!tg.hits) return out;
  out.hits = true;
  out.gradient = gap_gradient(tg.gradient, director_map(reference), node.offset);
  out.touch_travel = tg.travel + out.gradient.dot(coordinates);
  out.gap = out.touch_travel - travel;
  return out;
}

}  // namespace si
