// Pseudo-arclength continuation (Keller 1977): the unknowns are u = (x, p) and each corrector
// solves
//     F(x, p) = 0,    <d_x, x - x_a> + w^2 d_p (p - p_a) - ds = 0
// from the predictor u_a + ds d, where d is the unit tangent at u_a (or the unit secant), by the
// KINSOL corrector with Keller's bordered linear solve (bordered.hpp). Passes limit points of p.
// Tangents are oriented by the previous tangent; the first by Settings::direction (sign of dp).
// Theory: docs/theory/continuation.md.
#pragma once

#include "continuation/checkpoint.hpp"

namespace si::cont {

Branch pseudo_arclength(Problem& problem, Vector x0, double p0, const Settings& settings,
                        const Callback& callback = {});

// Continues the run saved in `resume` (written by pseudo_arclength with the same problem).
Branch pseudo_arclength(Problem& problem, const Checkpoint& resume, const Settings& settings,
                        const Callback& callback = {});

}  // namespace si::cont
