// The rigid indenter as a contact body of the indentation problem (indentation_problem.hpp): it
// moves along its unit direction of travel e by t0 + h, t0 its first touch of the shell's
// contact face (the face at offset c along the director from the reference surface) and h the
// depth. Built once: the face points of the reference configuration, the first touch, and the
// nodes the indenter can reach within a travel past it (the contact terms' first candidates).
#pragma once

#include <vector>

#include "contact/indenter.hpp"
#include "contact/node_gap.hpp"
#include "model/mesh.hpp"

namespace si {

class ContactBody {
 public:
  // Keeps a reference to the indenter. `reach`: how far past first touch (mm of travel) a node
  // may lie to be reachable. Throws an input error naming `indenter` if it never touches the
  // face along its direction or starts inside the shell, and one naming `indenter.direction` if
  // its travel at the first touch does not point into the face (it would come from behind).
  ContactBody(const Indenter& indenter, const Vector3d& direction, const Mesh& mesh,
              double face_offset, double reach);

  const Indenter& indenter() const { return indenter_; }
  const Vector3d& direction() const { return direction_; }
  double face_offset() const { return face_offset_; }
  double first_touch() const { return t0_; }
  // A gap below this is a touch, mm: roundoff of the travel and of the face points.
  double touch_roundoff() const { return touch_roundoff_; }
  // Per mesh node: its reference point and the face offset (node_gap.hpp).
  const NodeContactGeometry& geometry(int node) const { return geometry_[node]; }
  // Per mesh node: the face point of the reference configuration, X + c D.
  const std::vector<Vector3d>& face_points() const { return points_; }

  // The nodes whose face point the indenter reaches within `reach` of travel past first touch
  // (reference configuration), in node order, and the one it touches first.
  const std::vector<int>& reachable() const { return reachable_; }
  int first_node() const { return first_node_; }

 private:
  const Indenter& indenter_;
  Vector3d direction_;
  double face_offset_;
  std::vector<NodeContactGeometry> geometry_;
  std::vector<Vector3d> points_;
  double t0_ = 0;
  double touch_roundoff_ = 0;
  std::vector<int> reachable_;
  int first_node_ = -1;
};

}  // namespace si
