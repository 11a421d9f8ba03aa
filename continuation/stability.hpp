// The stability of a converged point as a Problem reports it (Problem::stability): the inertia of
// its symmetric tangent restricted to its constraints and the lowest eigenpairs
// (docs/theory/continuation.md, "Stability"). A problem builds it from its own matrices with
// analyse_stability (stability_analysis.hpp) and maps the modes to its unknowns.
#pragma once

#include <vector>

#include "continuation/linear_algebra.hpp"

namespace si::cont {

struct Stability {
  int negative = 0;    // negative eigenvalues of the restricted tangent (Sylvester count)
  int zero = 0;        // numerically zero ones: the point is critical to the pivots' accuracy
  Vector eigenvalues;  // the lowest ones, ascending
  // Their modes in the problem's unknowns x (a problem with multipliers may set the multipliers'
  // part with multiplier_direction(), or leave it zero: the corrector fixes it).
  std::vector<Vector> modes;
};

}  // namespace si::cont
