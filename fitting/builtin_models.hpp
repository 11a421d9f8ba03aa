// The curves fitted most often to indentation data, with analytic gradients and starting values
// guessed from the data. All are defined for x >= 0 (a depth).
//
//   power         y = C1 x^C2          the contact law T = C1 h^C2
//   hertz         y = C x^1.5          Hertz contact of a sphere (Johnson 1985, eq. 4.23)
//   power-offset  y = C1 x^C2 + C0     a power law on top of a constant offset (e.g. a preload)
//
// The power law in log space and polynomials are linear problems: linear_fit.hpp.
#pragma once

#include "fitting/curve_model.hpp"

namespace si::fit {

CurveModel power_law();
CurveModel hertz_law();
CurveModel power_law_with_offset();

}  // namespace si::fit
