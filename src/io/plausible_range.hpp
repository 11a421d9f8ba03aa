// Physical plausibility bounds applied when a case file is read. A value outside them is almost
// always a unit slip ("130 Pa" for 130 GPa, "0.475 m" for 0.475 mm) or a hostile input: caught
// at reading it is an error naming the key and line; caught later it was a numerical failure
// naming nothing (E = 1e-300 GPa failed deep in the solver). The bounds are generous - they
// refuse only what no laminate, shell or indenter can be.
#pragma once

#include <string>

#include "core/error.hpp"
#include "core/units.hpp"

namespace si {

struct PlausibleRange {
  double min;  // internal units
  double max;
  Dimension dimension;
  const char* what;  // "a modulus", for the message
};

// Moduli: 1 kPa (soft gels; structural foams are above 1 MPa) to 10 TPa (diamond 1.2 TPa).
constexpr PlausibleRange kModulusRange{1e-3, 1e7, Dimension::kStress, "a modulus"};
// Lengths (thicknesses, radii, sizes, depths): 1 nm to 1 km.
constexpr PlausibleRange kLengthRange{1e-6, 1e6, Dimension::kLength, "a length"};
// Forces: 1 nN to 1 TN.
constexpr PlausibleRange kForceRange{1e-9, 1e12, Dimension::kForce, "a force"};
// Pressures (loads): 1 mPa to 10 TPa.
constexpr PlausibleRange kPressureRange{1e-9, 1e7, Dimension::kStress, "a pressure"};

// Throws an input error at `where` unless min <= |value| <= max (zero is left to the caller's
// own check: many keys allow it, e.g. an edge radius).
void check_plausible(double value, const PlausibleRange& range, const Where& where);

}  // namespace si
