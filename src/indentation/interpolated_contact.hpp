// The paper's contact option (paper eqs 13-19, 26, 34, 72-76; issue #4 item 3): the contact
// traction is interpolated from nodal values, t_N = N~ t-bar_N (paper eq 15; N~ the bilinear
// corner functions, a partition of unity), and the contact work is an integral over the contact
// face, element by element. Linear kinematics only (the paper's setting, eqs 77-80).
//
// For traction node i (a candidate node) the weighted gap (mortar type) is
//     g~_i = int N_i g dA,      g(xi) = s(P(xi)) - t0 - h + a(xi) . delta p(xi)
// with P(xi) = sum_a N_a (X_a + c D_a) the reference point of the contact face (offset c along
// the director), s its touch travel and a = ds/dp (travel_gap.hpp), and delta p the face's
// displacement interpolated from the nodes' face displacements u_a + c E_a q_a (node_gap.hpp).
// So g~ = g~0 - h w + C~ x, with w_i = int N_i dA and g~0_i = int N_i (s(P) - t0) dA.
//
// F-bar coupling (paper eqs 13, 18, 75: the term t_N R^T F~ of the energy): the section's
// normal-traction coupling moves the loaded top face by -R^T Fbar+ along its normal n
// (vam.md 7.4: U3(h/2) = u3 - R^T Fbar+ + ..., with R the RM strains [e11, 2e12, e22, k11,
// k12 + k21, k22] at xi). The face displacement therefore gains -(R^T Fbar+) n, and the gap
// gains (a . n)(-R^T Fbar+). In the Lagrangian -t-bar . g~ with the compressive pressure
// p = t-bar >= 0 (vam.md 7.2: t+ = -p) and a . n = -1 (a face met head-on) this is the term
// +int t+ R^T Fbar+ dA of vam.md 7.4, i.e. the paper's U^T F_e N~ t-bar (eq 16) with the paper's
// t_N = t+ (its eq 20: t_N <= 0 in compression). R at xi is the element's own strain field, the
// bilinear field through its 2 x 2 Gauss-point strains (ShellElement::strains_at_nodes), linear
// in the element dofs in linear mode: R = B q (paper eq 18, F_e = int B^T F~ dA).
//
// Quadrature: n x n Gauss-Legendre points per element, or the nodal (lumped) rule - the four
// corners with unit weights - with which the option reduces to the nodal multipliers
// (t-bar_i w_i = lambda_i). A quadrature point beside the indenter's path (travel_gap misses)
// adds a far gap (1e6 mm) to g~0 and nothing to C~: its traction node is then never pressed.
#pragma once

#include <vector>

#include "contact/indenter.hpp"
#include "core/linalg.hpp"
#include "model/assembler.hpp"
#include "model/mesh.hpp"
#include "shell/shell_element.hpp"

namespace si {

struct InterpolatedContactOptions {
  int gauss_points = 2;  // per direction, 1..6; 0 = the nodal (lumped) rule
  bool fbar = false;     // add the F-bar coupling term
  // The section's Fbar+ (VamSection::Fbar_top) about the model's reference surface, in the
  // element's local frame: mm (membrane entries), mm^2 (bending entries); R^T Fbar+ is a length.
  Vector6d fbar_top = Vector6d::Zero();
};

// Where the contact face is and how the indenter moves (indentation_problem.hpp).
struct ContactFace {
  const Indenter& indenter;
  Vector3d direction;      // unit direction of travel e
  double offset = 0;       // c: contact face above the reference surface along the director, mm
  double first_touch = 0;  // t0, mm
};

// One row per candidate (traction node), in the candidates' order.
struct InterpolatedContact {
  SparseMatrix C;      // C~: candidates x free dofs (assembler.dofs() equations), mm^2 per mm|rad
  Eigen::VectorXd w;   // w_i = int N_i dA on the contact face, mm^2
  Eigen::VectorXd g0;  // g~0_i, mm^3
  std::vector<int> elements;  // the elements integrated: those with a candidate node
};

// Linear kinematics: `element` must be the assembler's element (its strain field gives B).
InterpolatedContact integrate_interpolated_contact(const Mesh& mesh, const Assembler& assembler,
                                                   const ShellElement& element,
                                                   const ContactFace& face,
                                                   const std::vector<int>& candidates,
                                                   const InterpolatedContactOptions& options);

}  // namespace si
