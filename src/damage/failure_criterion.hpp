// One entry point for the criteria of this directory, for callers that hold the criterion as a
// value (a monitor list, a case file's choice).
#pragma once

#include "damage/criterion_strengths.hpp"
#include "damage/failure_index.hpp"
#include "damage/material_stress.hpp"

namespace si {

// The criterion's index for a ply stress in material axes. `strengths` must come from
// strengths_for(criterion, material).
FailureIndex evaluate_criterion(Criterion criterion, const MaterialStress& stress,
                                const Strengths& strengths);

}  // namespace si
