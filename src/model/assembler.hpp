// Global assembly of the shell elements' internal force, tangent and strain energy.
//
// The tangent is stored over the FREE dofs only (DofMap equation numbers): prescribed dofs are
// eliminated, their values live in the nodal state. It is a CSC SparseMatrix with full (not
// triangular) storage, so that one matrix serves CHOLMOD (reads the lower triangle) and UMFPACK
// (non-symmetric follower-pressure tangents). Its pattern is built once, in the constructor,
// from the element connectivity; each element keeps the 20x20 value slots it writes to, so an
// assembly only zeroes the values and adds element blocks: no triplets, no sorting.
//
// Elements are computed in parallel with OpenMP. Elements are coloured so that no two elements
// of one colour share a node; the elements of one colour are computed and scattered in parallel
// (each thread with its own response buffer) without write conflicts. Because each matrix slot
// receives its contributions in the same colour order whatever the thread count, the assembled
// values do not depend on the number of threads.
//
// The internal force is a full dof vector: at prescribed dofs it gives the reactions
// (reactions() below). The Assembler keeps references to the mesh, dof map and element.
#pragma once

#include <vector>

#include "core/sparse.hpp"
#include "model/dof_map.hpp"
#include "model/mesh.hpp"
#include "shell/shell_element.hpp"

namespace si {

struct Assembly {
  SparseMatrix tangent;            // free x free
  Eigen::VectorXd internal_force;  // all dofs, N (N mm at rotation dofs)
  double energy = 0;               // total strain energy, N mm
};

class Assembler {
 public:
  // threads = 0: OpenMP's default number of threads.
  Assembler(const Mesh& mesh, const DofMap& dofs, const ShellElement& element, ShellLaw law,
            Kinematics kinematics, int threads = 0);

  // An Assembly with the tangent's pattern (values zero) and vectors of the right size.
  Assembly make_assembly() const;

  // Computes what `request` asks for at `state` (one NodeState per node) into `out`, which must
  // come from make_assembly(). The energy is always computed. An element's exception is
  // rethrown (after the parallel region); `out` is then incomplete.
  void assemble(const std::vector<NodeState>& state, const ElementRequest& request,
                Assembly& out) const;

  // tangent += scale * block, block in element dof order (rows/columns of prescribed dofs skipped).
  void add_element_block(int element, const Eigen::Matrix<double, 20, 20>& block, double scale,
                         SparseMatrix& tangent) const;

  std::array<NodeState, 4> element_states(const std::vector<NodeState>& state, int element) const;
  const ElementGeometry& geometry(int element) const { return geometry_[element]; }
  int num_colours() const { return static_cast<int>(colour_start_.size()) - 1; }
  const DofMap& dofs() const { return dofs_; }
  Kinematics kinematics() const { return kinematics_; }

 private:
  void build_pattern();
  void colour_elements();
  void compute_and_scatter(int element, const std::vector<NodeState>& state,
                           const ElementRequest& request, ElementResponse& response,
                           std::vector<double>& energy, Assembly& out) const;

  const Mesh& mesh_;
  const DofMap& dofs_;
  const ShellElement& element_;
  ShellLaw law_;
  Kinematics kinematics_;
  int threads_;
  std::vector<ElementGeometry> geometry_;
  SparseMatrix pattern_;
  // Value slot of entry (i, j) of element e's 20x20 block: slots_[400 e + 20 i + j], -1 where
  // the row or column is a prescribed dof.
  std::vector<int> slots_;
  // Elements sorted by colour: colour c is colour_order_[colour_start_[c] .. colour_start_[c+1]).
  std::vector<int> colour_order_;
  std::vector<int> colour_start_;
};

// Reactions: internal force minus external load at the prescribed dofs, zero at free dofs.
// At equilibrium, sum of reactions + sum of applied loads = 0 per direction.
Eigen::VectorXd reactions(const DofMap& dofs, const Eigen::VectorXd& internal_force,
                          const Eigen::VectorXd& external_force);

// The reference state of every node (u = 0, d = D, reference frame).
std::vector<NodeState> reference_state(const Mesh& mesh);

}  // namespace si
