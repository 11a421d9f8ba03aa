#include "core/units.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "core/constants.hpp"
#include "core/decimal_number.hpp"
#include "core/error.hpp"
#include "core/value_excerpt.hpp"

namespace si {
namespace {

struct UnitDef {
  const char* symbol;
  Dimension dim;
  double to_internal;  // multiply a value in this unit by this factor to get internal units
};

// Factors to mm, MPa, N, N*mm, deg, N/mm. Imperial units are exact by definition
// (1 in = 25.4 mm, 1 lbf = 4.4482216152605 N).
constexpr UnitDef kUnits[] = {
    {"mm", Dimension::kLength, 1.0},
    {"m", Dimension::kLength, 1000.0},
    {"cm", Dimension::kLength, 10.0},
    {"um", Dimension::kLength, 1e-3},
    {"µm", Dimension::kLength, 1e-3},
    {"in", Dimension::kLength, 25.4},
    {"Pa", Dimension::kStress, 1e-6},
    {"kPa", Dimension::kStress, 1e-3},
    {"MPa", Dimension::kStress, 1.0},
    {"GPa", Dimension::kStress, 1e3},
    {"N/mm^2", Dimension::kStress, 1.0},
    {"N/mm2", Dimension::kStress, 1.0},
    {"N/m^2", Dimension::kStress, 1e-6},
    {"psi", Dimension::kStress, 6.894757293168361e-3},
    {"ksi", Dimension::kStress, 6.894757293168361},
    {"Msi", Dimension::kStress, 6894.757293168361},
    {"N", Dimension::kForce, 1.0},
    {"kN", Dimension::kForce, 1e3},
    {"mN", Dimension::kForce, 1e-3},
    {"lbf", Dimension::kForce, 4.4482216152605},
    // A moment per length (an edge moment) is a force: N mm/mm = N.
    {"N*mm/mm", Dimension::kForce, 1.0},
    {"N*m/m", Dimension::kForce, 1.0},
    {"J", Dimension::kEnergy, 1e3},
    {"mJ", Dimension::kEnergy, 1.0},
    {"N*mm", Dimension::kEnergy, 1.0},
    {"Nmm", Dimension::kEnergy, 1.0},
    {"N*m", Dimension::kEnergy, 1e3},
    {"deg", Dimension::kAngle, 1.0},
    {"°", Dimension::kAngle, 1.0},
    {"rad", Dimension::kAngle, 180.0 / kPi},
    {"N/mm", Dimension::kFractureToughness, 1.0},
    {"kJ/m^2", Dimension::kFractureToughness, 1.0},
    {"kJ/m2", Dimension::kFractureToughness, 1.0},
    {"J/m^2", Dimension::kFractureToughness, 1e-3},
    {"J/m2", Dimension::kFractureToughness, 1e-3},
    {"N/m", Dimension::kFractureToughness, 1e-3},
    {"lbf/in", Dimension::kFractureToughness, 4.4482216152605 / 25.4},
};

std::string trim(std::string_view s) {
  size_t b = 0;
  size_t e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return std::string(s.substr(b, e - b));
}

std::string join(const std::vector<std::string>& parts) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : ", ") + p;
  return out;
}

// "a length", "an angle": for messages.
std::string with_article(Dimension dim) {
  const std::string name = dimension_name(dim);
  return (std::string("aeiou").find(name[0]) != std::string::npos ? "an " : "a ") + name;
}

const UnitDef* find_unit(const std::string& symbol) {
  for (const auto& u : kUnits)
    if (symbol == u.symbol) return &u;
  return nullptr;
}

}  // namespace

std::string dimension_name(Dimension dim) {
  switch (dim) {
    case Dimension::kLength:
      return "length";
    case Dimension::kStress:
      return "stress";
    case Dimension::kForce:
      return "force";
    case Dimension::kEnergy:
      return "energy";
    case Dimension::kAngle:
      return "angle";
    case Dimension::kFractureToughness:
      return "fracture toughness";
    case Dimension::kDimensionless:
      return "dimensionless number";
  }
  return "?";
}

std::string internal_unit(Dimension dim) {
  switch (dim) {
    case Dimension::kLength:
      return "mm";
    case Dimension::kStress:
      return "MPa";
    case Dimension::kForce:
      return "N";
    case Dimension::kEnergy:
      return "N*mm";
    case Dimension::kAngle:
      return "deg";
    case Dimension::kFractureToughness:
      return "N/mm";
    case Dimension::kDimensionless:
      return "";
  }
  return "";
}

std::vector<std::string> accepted_units(Dimension dim) {
  std::vector<std::string> out;
  for (const auto& u : kUnits)
    if (u.dim == dim) out.emplace_back(u.symbol);
  return out;
}

double parse_quantity(std::string_view text_in, Dimension dim) {
  const std::string text = trim(text_in);
  const Where where{"", "", text, 0};
  if (text.empty()) throw_input("empty value; expected " + with_article(dim), where);

  std::size_t length = 0;
  const std::optional<double> parsed = parse_decimal_prefix(text, length);
  if (!parsed) {
    throw_input(
        (is_hexadecimal(text) ? "a hexadecimal number: write it in decimal; expected "
                              : "not a number; expected ") +
            with_article(dim) +
            (dim == Dimension::kDimensionless ? "" : " such as '1 " + internal_unit(dim) + "'"),
        where);
  }
  const double number = *parsed;
  // Overflow ("1e999") and underflow to a denormal or zero ("1e-999") are both slips.
  if (!std::isfinite(number) || (number != 0.0 && std::abs(number) < 1e-300))
    throw_input("number out of range", where);

  const std::string unit = trim(text.substr(length));
  if (dim == Dimension::kDimensionless) {
    if (!unit.empty()) throw_input("expected a plain number without a unit", where);
    return number;
  }
  if (unit.empty()) {
    throw_input("missing unit: write the " + dimension_name(dim) + " with its unit, e.g. '" +
                    value_excerpt(text) + " " + internal_unit(dim) +
                    "' (accepted: " + join(accepted_units(dim)) + ")",
                where);
  }
  const UnitDef* def = find_unit(unit);
  if (def == nullptr) {
    throw_input("unknown unit '" + value_excerpt(unit) + "' for " + with_article(dim) +
                    " (accepted: " + join(accepted_units(dim)) + ")",
                where);
  }
  if (def->dim != dim) {
    throw_input("wrong unit: '" + unit + "' is " + with_article(def->dim) + " unit, expected " +
                    with_article(dim) + " (accepted: " + join(accepted_units(dim)) + ")",
                where);
  }
  return number * def->to_internal;
}

std::string format_quantity(double value, Dimension dim) {
  std::ostringstream os;
  os.precision(6);
  os << value;
  const std::string unit = internal_unit(dim);
  if (!unit.empty()) os << ' ' << unit;
  return os.str();
}

}  // namespace si
