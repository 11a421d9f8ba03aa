// Complementarity functions: phi(a, b) = 0  <=>  a >= 0, b >= 0, a b = 0. For contact,
// a = lambda (N) and b = kappa g (N), kappa a stiffness scale (N/mm) that gives the two
// comparable magnitudes.
//  * Fischer-Burmeister (Fischer 1992): phi = a + b - sqrt(a^2 + b^2); semismooth, with a
//    smooth merit function |phi|^2, so Newton with a line search (KINSOL) globalises it. At
//    (0, 0) an element of the generalised Jacobian is used: (1 - 1/sqrt 2, 1 - 1/sqrt 2).
//  * min: phi = min(a, b); semismooth Newton on it is the primal-dual active-set method
//    (Hintermueller, Ito & Kunisch 2002): active (b-row) where a > b.
//  * Fischer-Burmeister on the feasible quadrant, min outside it (the default of the KINSOL
//    runs): phi = FB(a, b) for a >= 0 and b >= 0, min(a, b) otherwise. Why: FB is homogeneous
//    of degree 1, and its Newton step from an infeasible point such as (0, -B) (a candidate the
//    predictor pushed through the indenter with no force yet) solves a + 2b = 2B, which
//    recovers only 2c / (1 + 2c) of the needed force (c the ratio of kappa to the node's contact
//    stiffness): Newton then converges linearly, by about 7x per iteration, until the iterate is
//    close (measured on the paper's cap: 5-6 iterations at every contact change instead of 2).
//    min is linear there (phi = b: the step closes the gap in one linearisation). Both pieces
//    vanish on the quadrant's edges and their gradients agree there ((1, 0) on a = 0 < b, (0, 1)
//    on b = 0 < a), so phi is C^1 except at the origin (as FB) and on the diagonal of the
//    infeasible third quadrant; it is FB wherever a solution lies, with its smoothness at the
//    tie a = b where min has a kink, and its solutions are FB's.
#pragma once

namespace si {

enum class NcpFunction { kFischerBurmeister, kMin, kFischerBurmeisterMin };

struct NcpValue {
  double value = 0;
  double d_a = 0;  // d phi / d a
  double d_b = 0;  // d phi / d b
};

NcpValue ncp(NcpFunction f, double a, double b);

}  // namespace si
