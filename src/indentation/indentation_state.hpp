// What the indentation problem reports at a point (indentation_problem.hpp): the state a user
// wants, the quantities a continuation monitors, and the work counters.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/linalg.hpp"
#include "damage/monitored_failure.hpp"

namespace si {

// Everything a user wants at one converged point (whole-shell values: symmetry applied).
struct IndentationState {
  double depth = 0;            // h, mm
  double force = 0;            // T_N = sum of multipliers, N
  double reaction = 0;         // support reactions along -e, N (equals force at equilibrium), a
                               // support frame's included
  double apex_deflection = 0;  // apex mid-surface displacement along e, mm
  // The laminate's apex mid-plane displacement: apex_deflection plus the elastic face's mid-plane
  // share (elastic_face.hpp), mm.
  double apex_mid_deflection = 0;
  double contact_radius = 0;  // largest distance from the indenter's axis of a node in contact
  double contact_area = 0;    // tributary area of the nodes in contact, mm^2
  int contact_nodes = 0;      // nodes in contact (whole-shell count is not reconstructed)
  double energy = 0;          // strain energy, N mm
  // The point's estimated relative energy-norm discretisation error (model/recovery_error.hpp,
  // Zienkiewicz-Zhu).
  double error_estimate = 0;
  // Local contact (zero without): the approach of the indenter towards the contact face at the
  // apex (alpha for a power law, c_L p at the apex node for the thin layer), mm, and the energy
  // stored in the local compliance, N mm (work = energy + local_energy).
  double local_indentation = 0;
  double local_energy = 0;
  Vector3d apex_curvature = Vector3d::Zero();  // k11, k12 + k21, k22 at the apex, 1/mm
  // Extremes of the same curvatures over the nodes in contact (paper-notes item 7: the paper's
  // figures do not say where their curvatures are taken). Quarter models: k12 changes sign in
  // the mirrored quadrants, so its extremes are -+ max |k12|.
  Vector3d contact_curvature_min = Vector3d::Zero(), contact_curvature_max = Vector3d::Zero();
  // KKT residuals: min gap (mm), min multiplier (N), max |lambda_i g_i| (N mm).
  double min_gap = 0, min_multiplier = 0, max_complementarity = 0;
  std::vector<int> nodes;           // candidate nodes
  std::vector<double> multipliers;  // lambda per candidate, N
  std::vector<double> gaps;         // g per candidate, mm
  std::vector<double> pressures;    // lambda / tributary area per candidate, MPa (interpolated
                                    // traction: lambda / w = t-bar, the nodal traction)
  // A support frame under the shell (indentation/support_frame.hpp; zero and empty without):
  // its whole-shell force along its normal (N), the nodes bearing on it, and per frame candidate
  // its node, multiplier (N) and gap to the frame (mm).
  double frame_force = 0;
  int frame_contact_nodes = 0;
  std::vector<int> frame_nodes;
  std::vector<double> frame_multipliers;
  std::vector<double> frame_gaps;
  // The largest failure index of each criterion (by Criterion) over the monitored points, where
  // the run monitors damage (IndentationOptions::probe; index NaN otherwise).
  std::array<MonitoredFailure, kCriteria> failure;
};

// Work done so far, for benchmarks and the run summary.
struct IndentationCounters {
  long residuals = 0;           // residual() calls (an assembly unless the last one was at z)
  long factorizations = 0;      // factorize() calls: Jacobian fills + factorizations
  long solves = 0;              // back-substitutions
  long evaluations = 0;         // evaluate() calls that were not cached (output, monitors)
  long tangent_assemblies = 0;  // element assemblies actually computed, force + tangent
  long force_assemblies = 0;    // and force only (nonlinear kinematics)
  // Stability analyses (path.stability) from the Krylov preconditioner's own factor, and by the
  // direct route (Z'HZ factored: another point, a direct solver, or not positive definite).
  long stability_from_preconditioner = 0;
  long stability_direct = 0;
};

// A quantity of the state the continuation follows (Problem::monitors; the path's result
// columns say which: analysis/path_columns.hpp). It must need no assembly: it is evaluated off
// the branch too, from the force, the apex deflection and curvatures and the contact extent.
struct StateMonitor {
  std::string name;
  double (*value)(const IndentationState&) = nullptr;
  // Reads the damage probe's part of the state (IndentationProblem::set_probe): the costly one.
  bool probed = false;
};

}  // namespace si
