// What a failure criterion returns for one ply stress state: an index that is 1 at onset, the
// governing mode, and the criterion's function in its published form.
//
// The index is the inverse of the load factor to onset under proportional loading: scaling the
// stress by 1/index brings the criterion exactly to onset. It is therefore >= 0, linear in the
// load, 1 exactly where the published criterion reaches 1, and comparable between criteria
// (Tsai-Wu's function alone is neither: it is quadratic with linear terms and may be negative).
// Every criterion here is of the form F(R sigma) = a R^2 + b R with a >= 0 or a single mode of
// that form, so index = (b + sqrt(b^2 + 4a)) / 2 and the published value is F(sigma) = a + b.
#pragma once

namespace si {

enum class Criterion {
  kMaxStress,              // maximum stress, 3-D (max_stress.hpp)
  kTsaiWu,                 // Tsai-Wu, 3-D (tsai_wu.hpp)
  kHashin,                 // Hashin 1980, 3-D, four modes (hashin.hpp)
  kQuadraticDelamination,  // Brewer & Lagace 1988 on interfaces (quadratic_delamination.hpp)
};

enum class FailureMode {
  kNone,               // zero stress, or a state that never reaches onset when scaled up
  kFibreTension,       // sigma11 > 0 governs
  kFibreCompression,   // sigma11 < 0 governs
  kMatrixTension,      // transverse tension (Hashin: sigma22 + sigma33 >= 0; max stress: sigma22)
  kMatrixCompression,  // transverse compression
  kNormalTension,      // max stress: sigma33 against Z_T
  kNormalCompression,  // max stress: sigma33 against Z_C
  kShear12,            // max stress: in-plane shear
  kShear13,            // max stress: longitudinal interlaminar shear
  kShear23,            // max stress: transverse shear
  kDelamination,       // interlaminar criterion on an interface
};

struct FailureIndex {
  double index = 0;            // inverse load factor to onset (header); 1 = onset
  double criterion_value = 0;  // the published function F(sigma); 1 = onset
  FailureMode mode = FailureMode::kNone;
};

// The index of F(R sigma) = a R^2 + b R (header): the inverse of the smallest positive root of
// F = 1, or 0 when F never reaches 1 along the ray.
double inverse_load_factor(double a, double b);

// A failure mode of the form F(R sigma) = a R^2 + b R, as a FailureIndex.
FailureIndex quadratic_mode(double a, double b, FailureMode mode);

// The larger index of two (the governing mode); ties keep the first.
FailureIndex governing(const FailureIndex& first, const FailureIndex& second);

}  // namespace si
