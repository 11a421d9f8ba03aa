// Natural-parameter continuation: step p, predict x (tangent dx/dp = -J^-1 F_p, or secant),
// correct at fixed p with the KINSOL corrector. Cannot pass a limit point of p: there the
// corrector fails, the step halves down to step_min and the run ends with kStepTooSmall,
// keeping every converged point. Steps are |dp|; Settings::parameter_values are hit exactly.
#pragma once

#include "continuation/checkpoint.hpp"

namespace si::cont {

Branch natural(Problem& problem, Vector x0, double p0, const Settings& settings,
               const Callback& callback = {});

// Continues the run saved in `resume` (written by natural with the same problem).
Branch natural(Problem& problem, const Checkpoint& resume, const Settings& settings,
               const Callback& callback = {});

}  // namespace si::cont
