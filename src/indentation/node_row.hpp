// One complementarity row on one node's five dofs, as the nodal contact rows of a contact body
// have it (the indenter's nodal gaps, nodal_gaps.hpp; the support frame, support_frame.hpp): the
// multiplier m couples to the node's equations only, with the Jacobian entries
//     shell rows:  -G (column m),  -lambda dG (node block, nonlinear kinematics)
//     row m:        phi_b kappa G^T,  phi_a (diagonal)
// for the gap gradient G and its derivative dG (contact/node_gap.hpp).
#pragma once

#include <array>

#include "contact/node_gap.hpp"
#include "indentation/contact_jacobian_solver.hpp"
#include "indentation/contact_term.hpp"
#include "model/dof_map.hpp"

namespace si {

// Value slots in J of a row's entries on its node's equations (-1 where prescribed).
struct NodeRowSlots {
  std::array<int, 5> eq{};      // equations of the node's 5 dofs
  std::array<int, 25> block{};  // (eq[r], eq[c]) at 5 r + c
  std::array<int, 5> column{};  // (eq[r], multiplier)
  std::array<int, 5> row{};     // (multiplier, eq[c])
  int diagonal = -1;            // (multiplier, multiplier)
  int alpha_column = -1;        // (multiplier, alpha), with a local law's alpha (index `alpha`)
};

// The pattern of the row of multiplier m (index in z) on mesh node `node`; alpha < 0: none.
void add_node_row_pattern(const DofMap& dofs, int node, int m, int alpha, Triplets& t);
NodeRowSlots locate_node_row(const DofMap& dofs, int node, int m, int alpha, const SparseMatrix& J);

// r_free -= lambda G: the row's force lambda G on its node's free dofs.
void add_node_row_force(const NodeRowSlots& s, const NodeGap& g, double lambda,
                        Eigen::VectorXd& r_free);

// The entries above, except the diagonal (and the alpha column), into J's values: `b` is
// phi_b kappa, `lambda` the multiplier (the node block is added only if `derivative`).
void add_node_row_entries(const NodeRowSlots& s, const NodeGap& g, double lambda, double b,
                          bool derivative, double* J);

// The row for the Krylov solver's condensed preconditioner: a = d phi / d lambda, b = phi_b kappa.
ContactJacobianRow condensed_node_row(const NodeRowSlots& s, const NodeGap& g, double a, double b);

}  // namespace si
