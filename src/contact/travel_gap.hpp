// The gap along the direction of travel (the paper's eq 23, g_N = w - f - h): for a point p,
// s(p) is the travel at which the moving indenter's surface reaches p, and the gap of p at
// travel h is s(p) - h. Because each indenter is a rigid shape translated along its unit
// direction e, phi(p, t) = phi_0(p - t e) and s(p) solves phi(p, s) = 0 on the side the indenter
// arrives from (n . e > 0, n the indenter's outward normal at p). Derivatives, from the implicit
// function theorem:
//     ds/dp = n / (n.e),     d2s/dp2 = Q^T H Q / (n.e),   Q = I - e n^T / (n.e),
// with H = dn/dx the derivative of the unit normal field (only its tangential part enters: Q
// projects on the tangent plane). ds/dp . e = 1, so a multiplier lambda on this gap is the
// contact force component along the direction of travel, and the contact force lambda ds/dp is
// normal to the indenter (frictionless). docs/theory/contact.md.
#pragma once

#include "contact/indenter.hpp"

namespace si {

struct TravelGap {
  bool hits = false;  // false: p lies beside the indenter's path (the ray misses or grazes it)
  double travel = 0;  // s(p), mm
  Vector3d gradient = Vector3d::Zero();
  Matrix3d hessian = Matrix3d::Zero();  // only if asked for
};

// Grazing limit: where n.e is below this, the point is treated as beside the indenter's path
// (the gradient 1/(n.e) would blow up; such points are never pressed in practice).
constexpr double kGrazingCosine = 1e-6;

// `direction` is the indenter's unit direction of travel; `guess` a travel near s(p) (e.g. the
// current travel or the last s(p)). Newton on phi(p, t) = 0 from the guess, with the indenter's
// own first_touch (sphere tracing) as a fall-back; converged to 1e-14 relative.
TravelGap travel_gap(const Indenter& indenter, const Vector3d& direction, const Vector3d& p,
                     double guess, bool want_hessian);

}  // namespace si
