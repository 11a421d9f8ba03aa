// What the library knows about a converged point beyond (x, p): the unit tangent (oriented by a
// reference direction), the Jacobian sign, the signature, the monitors, when events need them the
// monitors' first and second derivatives along the branch, and when asked its stability.
//
// Derivatives along the arclength s (docs/theory/continuation.md, "Derivatives along the branch"):
//   m'  = grad m . t                       central difference along t, step h1 = eps^(1/3) S
//   u'' solves [J F_p; t'] u'' = [-F_uu[t,t]; 0]   (differentiate F(u(s)) = 0 twice, and
//        <t, t> = 1 once), with F_uu[t,t] from the second difference of F along t, h2 = eps^(1/4) S
//   m'' = m_uu[t,t] + grad m . u''         second difference along t (h2) + central along u''
// with S = 1 + ||u|| in the arclength norm. Errors: O(h1^2) + O(eps/h1) ~ 1e-10 relative for m',
// O(h2^2) + O(eps/h2^2) ~ 1e-8 relative for m''. For the curve-feature detector the second
// derivatives are computed again with 2 h2: |m''(h2) - m''(2 h2)| estimates the error of m''(h2)
// (3x its truncation error, about its roundoff), floored by 4 eps |m| / h2^2; the same for p''.
#pragma once

#include "continuation/bordered.hpp"
#include "continuation/branch.hpp"

namespace si::cont {

struct TangentPoint {
  Point point;
  Vector tangent_x;           // x part of the unit tangent (the p part is point.tangent_p)
  std::vector<Vector> modes;  // stability: the lowest eigenmodes (Point::eigenvalues' order)
};

struct AnalysisNeeds {
  // false: the monitors alone (and the signature if asked), no factorization: what the location
  // of a monitor's level crossing reads at its trial points. The tangent, jacobian_sign and every
  // derivative are then left at their defaults, and the Jacobian is not factored at (x, p).
  bool tangent = true;
  // The derivatives below are computed for these monitors (ascending indices), NaN for the rest:
  // a monitor's derivative costs two or more evaluations of the monitors off the branch.
  std::vector<int> derivative_monitors;
  bool slopes = false;            // monitor_slopes
  bool curvatures = false;        // monitor_curvatures (implies slopes)
  bool curvature_errors = false;  // + their error estimates and p'' (implies curvatures)
  bool signature = false;
  int stability_modes = 0;  // Problem::stability with this many modes (0 = not asked)
};

// Fills out (x, p, tangent_p, monitors, derivatives, signature, jacobian_sign, stability and
// modes, tangent_x) at a converged (x, p), the tangent oriented so that <ref, t> > 0 (ref_x may be
// empty: orientation by the sign of ref_p alone); every other Point field is reset to its default.
// Leaves the Jacobian factored at (x, p). false when the factorization, dF/dp or the stability
// analysis fails there.
bool analyse_point(Problem& problem, BorderedSolver& bordered, const Vector& x, double p,
                   const Vector& ref_x, double ref_p, const AnalysisNeeds& needs,
                   TangentPoint& out);

}  // namespace si::cont
