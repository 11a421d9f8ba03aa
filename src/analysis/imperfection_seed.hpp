// The shape of a geometric imperfection seeded from a critical mode (docs/case-file.md
// `path.imperfection`), as engineers do with Riks: the perfect shell's path is traced with its
// stability up to the first change (a bifurcation or a limit point of the depth), the lowest
// eigenpairs of the restricted tangent are computed there (docs/theory/continuation.md 12), and
// the chosen mode, scaled to the amplitude, is added to the mesh (model/geometric_imperfection.hpp)
// before the imperfect shell's path is traced. A path without any change seeds the mode at its
// last point and says so.
#pragma once

#include <Eigen/Dense>
#include <limits>

#include "analysis/path_spec.hpp"
#include "continuation/branch.hpp"
#include "indentation/jacobian_solver.hpp"

namespace si {

struct IndentationCase;

struct ImperfectionSeed {
  ImperfectionSpec spec;
  bool at_stability_change = false;  // else at the perfect path's last point
  double depth = 0.0;                // mm of travel after first touch, where the mode was taken
  double force = 0.0;                // N, whole shell, there
  double eigenvalue = std::numeric_limits<double>::quiet_NaN();  // of the mode, N/mm (chart)
  cont::Criticality criticality = cont::Criticality::kNone;      // of the change, if any
  int perfect_points = 0;  // converged points of the perfect path traced
  // The translations added to the mesh's nodes (mm, rows = nodes): amplitude times the mode's
  // translations, the largest 1 and its largest component positive (the eigen-solver's sign is
  // arbitrary; this one is reproducible).
  Eigen::MatrixXd shape;
};

// Traces the perfect path of `c` (its imperfection removed, path.stability on, no damage) to its
// first stability change or its end, and takes mode c.path.imperfection->mode there. Throws an
// input error naming path.imperfection when the perfect path does not start or the modes cannot
// be computed.
ImperfectionSeed seed_imperfection(const IndentationCase& c, int threads,
                                   JacobianSolverKind linear_solver);

}  // namespace si
