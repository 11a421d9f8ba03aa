// Where a run stands between two steps: everything the next step needs, and so everything a
// checkpoint must hold to resume bit for bit (with the branch so far).
#pragma once

#include <limits>

#include "continuation/point_analysis.hpp"

namespace si::cont {

struct State {
  TangentPoint current;  // the last accepted point (after Problem::adapt) and its unit tangent
  double step = 0.0;     // the next nominal step size
  // The accepted point before it, for the secant predictor (invalid after an adaptation).
  bool has_previous = false;
  Vector previous_x;
  double previous_p = 0.0;
  // dp/ds of the unit tangent at the accepted point before `current` (NaN: none). Kept through
  // an adaptation (a scalar slope of the branch): the natural corrector's fold guard reads it
  // (ArclengthStepper::steep_ahead).
  double previous_tangent_p = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace si::cont
