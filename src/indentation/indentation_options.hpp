// The choices of an indentation problem (indentation_problem.hpp); the runs fill them from the
// case's contact and path (analysis/indentation_run.cpp).
#pragma once

#include <optional>
#include <vector>

#include "contact/local_contact_law.hpp"
#include "contact/ncp_function.hpp"
#include "indentation/indentation_state.hpp"
#include "indentation/interpolated_contact.hpp"
#include "indentation/jacobian_solver.hpp"

namespace si {

struct IndentationOptions {
  double contact_offset = 0;  // c: contact face above the reference surface along d, mm
  // c of the face that rests on a support frame (the back face), with a model that has one
  // (ShellModel::frame_nodes, support_frame.hpp).
  double frame_offset = 0;
  double candidate_depth = 12;  // mm of travel past first touch (contact_rows.hpp)
  // Fischer-Burmeister on the feasible quadrant, min outside (ncp_function.hpp); kMin for the
  // active-set cross-check.
  NcpFunction ncp = NcpFunction::kFischerBurmeisterMin;
  // The interpolated traction's rows span several nodes: it uses the direct LU (UMFPACK unless
  // klu is asked for). A power-law local contact's unknown alpha borders the Krylov solver's
  // matrix (contact_jacobian_solver.hpp).
  JacobianSolverKind linear_solver = JacobianSolverKind::kPreconditionedKrylov;
  // kPreconditionedKrylov: GMRES stops at a relative residual of krylov_tolerance. The Newton
  // corrections need no more than 1e-6: an inexact Newton method with a constant forcing term
  // (Dembo, Eisenstat & Steihaug 1982, SIAM J. Numer. Anal. 19:400-408) has
  // ||F_k+1|| <= eta ||F_k|| + O(||F_k||^2), and eta = 1e-6 is far below the contraction Newton
  // reaches within the corrector's tolerance: the iteration counts are those of exact solves
  // (measured identical on the 1e4-unknown cap over 0-10 mm) at 2.5 instead of 3.9 products per
  // solve. Convergence is judged on the residual, so eta does not limit the solution's accuracy;
  // the tangents and the bordered solves of the continuation carry errors of order eta.
  double krylov_tolerance = 1e-6;
  int threads = 0;  // element assembly (0 = OpenMP default)
  // The paper's option (contact.traction: interpolated), linear kinematics only: weighted gaps
  // with the interpolated traction (weighted_gaps.hpp) instead of nodal gaps (nodal_gaps.hpp).
  bool interpolated_traction = false;
  InterpolatedContactOptions interpolated;
  LocalContactLaw local;  // local contact in series (none by default)
  // The elastic face (local_support: shell) couples the contact nodes within a zone around the
  // first touch that follows the contact up to this radius (mm; 0: all candidates): the Newton
  // paths' Jacobian holds a dense block over them. The runs take the sphere's chord at the
  // path's depth, an upper bound of the contact radius, or -1 where the linear fast path solves
  // it: every pair coupled, no Newton block (elastic_face.hpp).
  double face_zone_bound = 0;
  // contact.fbar with the nodal traction (face_thickening.hpp), linear kinematics only: the
  // section's Fbar+ (VamSection::Fbar_top); with the interpolated traction it is interpolated.fbar.
  std::optional<Vector6d> nodal_fbar;
  // What the continuation monitors (Problem::monitor_names), in order; none by default (the
  // runs pass the monitor columns of analysis/path_columns.hpp).
  std::vector<StateMonitor> monitors;
};

}  // namespace si
