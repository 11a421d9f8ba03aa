// External loads at load factor 1; the static solver multiplies all of them by the load factor.
// Point, line and pressure loads act on the translation dofs; nodal moments (below) on the
// rotation dofs. Vectors are full dof vectors (dof_map.hpp numbering, 5 per node), forces in N,
// moments in N mm.
//
// Pressure: the traction is p n on the mid-surface, n the unit normal of the element surface
// oriented by the node order (counter-clockwise about the directors, so n agrees with them): a
// positive p pushes the surface towards its director side. Consistent nodal forces with the
// bilinear shape functions and 2x2 Gauss points, f_a = p sum_g N_a(g) (x_xi x x_eta)(g),
// exact for flat elements. A dead pressure uses the reference positions X (fixed direction
// and area); a follower pressure uses the current positions x = X + u, so its nodal forces
// depend on the state and it contributes a load stiffness -lambda df/dx, non-symmetric in
// general, to the tangent.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/mesh.hpp"
#include "shell/director.hpp"

namespace si {

struct PointLoad {
  std::string node_set;
  Vector3d force = Vector3d::Zero();  // N
  bool per_node = false;              // false: `force` is the total, split equally over the set
};

// A load per unit length along an edge given as an ordered list of nodes (consecutive nodes are
// joined by straight segments). Each segment of reference length L carries q L, half to each
// end: the consistent load of a constant q with linear interpolation.
struct LineLoad {
  std::vector<int> edge_nodes;
  Vector3d force_per_length = Vector3d::Zero();  // N/mm
};

// A moment M applied at the nodes of a set. The rotation dofs a, b of a node are rotation
// increments about its axes v1, v2 (shell_element.hpp), so the virtual work of M is
// M . (delta a v1 + delta b v2): the generalised forces are M . v1 and M . v2. They are taken
// with the REFERENCE axes V1, V2 (director.hpp) and kept constant, a load that does not depend
// on the state. This is the work of the moment M exactly while M . v1 and M . v2 keep their
// reference values, e.g. a moment about a fixed axis that is one of the node's axes and about
// which all its rotation takes place (plane bending: the axis stays v1 or v2; Sze, Liu & Lo
// 2004, cantilever rolled up by an end moment). For general 3-D rotations it is neither a
// fixed-axis nor a follower moment. A component of M along the director (drilling) has no dof
// to act on and is refused.
struct NodalMoment {
  std::string node_set;
  Vector3d moment = Vector3d::Zero();  // N mm
  bool per_node = false;               // false: `moment` is the total, split equally over the set
};

struct PressureLoad {
  double pressure = 0;        // MPa
  bool follower = false;      // follows the deformed surface (see above)
  std::vector<int> elements;  // empty: all elements of the mesh
};

struct Loads {
  std::vector<PointLoad> points;
  std::vector<LineLoad> lines;
  std::vector<PressureLoad> pressures;
  std::vector<NodalMoment> moments;

  bool has_follower() const;
};

// True when `moment` has a component along `director` (|M . D| > 1e-12 |M|): a drilling
// moment, which the 5-dof nodes cannot carry (NodalMoment).
bool is_drilling(const Vector3d& moment, const Vector3d& director);

// Throws an input error for unknown node sets, nodes or elements out of range, a line load with
// fewer than 2 nodes or a zero-length segment, a nodal moment with a component along a node's
// director (|M . D| > 1e-12 |M|), or a non-finite value.
void validate(const Mesh& mesh, const Loads& loads);

// Point, line, nodal moment and dead pressure loads (everything that does not depend on the
// state).
Eigen::VectorXd fixed_load_vector(const Mesh& mesh, const Loads& loads);

// Follower pressure loads at the current nodal positions.
Eigen::VectorXd follower_load_vector(const Mesh& mesh, const Loads& loads,
                                     const std::vector<NodeState>& state);

// Visits every element carrying a follower pressure with the derivative of its nodal forces
// with respect to its nodal translations (20x20 in element dof order, rotation rows/columns
// zero). The tangent of the residual f_int - lambda f_ext gets -lambda times these blocks.
template <class Visitor>
void for_each_follower_stiffness(const Mesh& mesh, const Loads& loads,
                                 const std::vector<NodeState>& state, Visitor&& visit);

// Element level (x = 4 nodal positions): consistent nodal forces (12, node-major) of pressure p,
// and their derivative with respect to x (12x12).
Eigen::Matrix<double, 12, 1> pressure_nodal_forces(const std::array<Vector3d, 4>& x, double p);
Eigen::Matrix<double, 12, 12> pressure_load_stiffness(const std::array<Vector3d, 4>& x, double p);

// ---- implementation of the template

std::array<Vector3d, 4> current_positions(const Mesh& mesh, const std::vector<NodeState>& state,
                                          int element);

template <class Visitor>
void for_each_follower_stiffness(const Mesh& mesh, const Loads& loads,
                                 const std::vector<NodeState>& state, Visitor&& visit) {
  Eigen::Matrix<double, 20, 20> block;
  const auto one = [&](int e, double p) {
    const Eigen::Matrix<double, 12, 12> k =
        pressure_load_stiffness(current_positions(mesh, state, e), p);
    block.setZero();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) block.block<3, 3>(5 * a, 5 * b) = k.block<3, 3>(3 * a, 3 * b);
    visit(e, static_cast<const Eigen::Matrix<double, 20, 20>&>(block));
  };
  for (const PressureLoad& pl : loads.pressures) {
    if (!pl.follower) continue;
    if (pl.elements.empty()) {
      for (int e = 0; e < mesh.num_elements(); ++e) one(e, pl.pressure);
    } else {
      for (int e : pl.elements) one(e, pl.pressure);
    }
  }
}

}  // namespace si
