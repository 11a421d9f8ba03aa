// Complementarity functions: phi(a, b) = 0  <=>  a >= 0, b >= 0, a b = 0. For contact,
// a = lambda (N) and b = kappa g (N), kappa a stiffness scale (N/mm) that gives the two
// comparable magnitudes.
//  * Fischer-Burmeister (Fischer 1992): phi = a + b - sqrt(a^2 + b^2); semismooth, with a
//    smooth merit function |phi|^2, so Newton with a line search (KINSOL) globalises it. At
//    (0, 0) an element of the generalised Jacobian is used: (1 - 1/sqrt 2, 1 - 1/sqrt 2).
//  * min: phi = min(a, b); semismooth Newton on it is the primal-dual active-set method
//    (Hintermueller, Ito & Kunisch 2002): active (b-row) where a > b.
#pragma once

namespace si {

enum class NcpFunction { kFischerBurmeister, kMin };

struct NcpValue {
  double value = 0;
  double d_a = 0;  // d phi / d a
  double d_b = 0;  // d phi / d b
};

NcpValue ncp(NcpFunction f, double a, double b);

}  // namespace si
