// Quantities with explicit units, as users write them in case files and on the command line
// ("130 GPa", "0.475 mm", "45 deg"). Internal units are fixed for the whole code:
//   length mm, stress/modulus MPa (= N/mm^2), force N, energy N*mm (= mJ), angle deg,
//   fracture toughness (energy per crack area) N/mm (= kJ/m^2).
// Conversion happens here, once, at input; nothing downstream multiplies by unit factors.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace si {

enum class Dimension {
  kLength,
  kStress,
  kForce,
  kEnergy,
  kAngle,
  kFractureToughness,
  kDimensionless
};

// Name of a dimension ("length") and of its internal unit ("mm").
std::string dimension_name(Dimension dim);
std::string internal_unit(Dimension dim);

// The unit spellings accepted for a dimension, for error messages and --help.
std::vector<std::string> accepted_units(Dimension dim);

// Parses "<number> <unit>" (space optional) and returns the value in internal units.
// A dimensional quantity without a unit is refused (the user must say what they mean);
// a dimensionless one takes a bare number. Throws si::Error (kind kInput) naming the text.
double parse_quantity(std::string_view text, Dimension dim);

// Formats an internal-unit value with its internal unit, e.g. "0.475 mm".
std::string format_quantity(double value, Dimension dim);

}  // namespace si
