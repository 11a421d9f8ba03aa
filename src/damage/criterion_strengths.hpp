// The strengths a failure criterion reads, taken from a material once (before a path starts), so
// that a material without them is refused up front with the material and the key named, and the
// criteria themselves are pure functions of numbers.
#pragma once

#include <vector>

#include "damage/failure_index.hpp"
#include "material/material.hpp"

namespace si {

// MPa, magnitudes (material/ply_strengths.hpp). Entries the criterion does not read are NaN.
struct Strengths {
  double X_T, X_C, Y_T, Y_C, Z_T, Z_C, S_12, S_13, S_23;
};

// The keys each criterion reads:
//   max stress, Tsai-Wu (both 3-D): all nine;
//   Hashin (1980): X_T, X_C, Y_T, Y_C, S_12 (axial shear, 12 and 13 planes), S_23 (transverse);
//   quadratic delamination (Brewer & Lagace): Z_T, S_13, S_23.
std::vector<StrengthKey> required_strengths(Criterion criterion);

// Throws an input si::Error naming the material, the missing key and the criterion when the
// material lacks a strength the criterion reads (its key is the strength's name, its value the
// material's name).
Strengths strengths_for(Criterion criterion, const Material& material);

// The criterion's name for messages: "maximum stress", "Tsai-Wu", "Hashin",
// "quadratic delamination".
const char* criterion_name(Criterion criterion);

}  // namespace si
