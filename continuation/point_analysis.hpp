// What the library knows about a converged point beyond (x, p): the unit tangent (oriented by a
// reference direction), the Jacobian sign, the signature, the monitors and, when events need
// them, the monitors' first and second derivatives along the branch.
//
// Derivatives along the arclength s (docs/theory/continuation.md, "Derivatives along the branch"):
//   m'  = grad m . t                       central difference along t, step h1 = eps^(1/3) S
//   u'' solves [J F_p; t'] u'' = [-F_uu[t,t]; 0]   (differentiate F(u(s)) = 0 twice, and
//        <t, t> = 1 once), with F_uu[t,t] from the second difference of F along t, h2 = eps^(1/4) S
//   m'' = m_uu[t,t] + grad m . u''         second difference along t (h2) + central along u''
// with S = 1 + ||u|| in the arclength norm. Errors: O(h1^2) + O(eps/h1) ~ 1e-10 relative for m',
// O(h2^2) + O(eps/h2^2) ~ 1e-8 relative for m''.
#pragma once

#include "continuation/bordered.hpp"
#include "continuation/branch.hpp"

namespace si::cont {

struct TangentPoint {
  Point point;
  Vector tangent_x;  // x part of the unit tangent (the p part is point.tangent_p)
};

struct AnalysisNeeds {
  bool slopes = false;      // monitor_slopes
  bool curvatures = false;  // monitor_curvatures (implies slopes)
  bool signature = false;
};

// Fills out.point (x, p, tangent_p, monitors, derivatives, signature, jacobian_sign) and
// out.tangent_x at a converged (x, p), the tangent oriented so that <ref, t> > 0 (ref_x may be
// empty: orientation by the sign of ref_p alone). Leaves the Jacobian factored at (x, p).
// false when the factorization or dF/dp fails there.
bool analyse_point(Problem& problem, BorderedSolver& bordered, const Vector& x, double p,
                   const Vector& ref_x, double ref_p, const AnalysisNeeds& needs,
                   TangentPoint& out);

}  // namespace si::cont
