#include "material/ply_strengths.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace si {
namespace {

constexpr const char* kStrengthNames[kStrengthKeys] = {"X_T", "X_C",  "Y_T",  "Y_C", "Z_T",
                                                       "Z_C", "S_12", "S_13", "S_23"};
constexpr const char* kToughnessNames[kToughnessKeys] = {"G_Ic", "G_IIc"};

std::string num(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

void require_positive(const std::optional<double>& value, const char* key, const char* unit) {
  if (!value) return;
  if (!(*value > 0.0) || !std::isfinite(*value))
    throw_input(
        std::string(key) + " must be positive and finite (got " + num(*value) + " " + unit + ")",
        Where{"", key, num(*value) + " " + unit, 0});
}

}  // namespace

const char* key_name(StrengthKey key) {
  return kStrengthNames[static_cast<int>(key)];
}

const char* key_name(ToughnessKey key) {
  return kToughnessNames[static_cast<int>(key)];
}

bool PlyStrengths::empty() const {
  for (const auto& v : values)
    if (v) return false;
  return true;
}

bool FractureToughness::empty() const {
  for (const auto& v : values)
    if (v) return false;
  return true;
}

void validate(const PlyStrengths& strengths) {
  for (int k = 0; k < kStrengthKeys; ++k)
    require_positive(strengths.values[k], kStrengthNames[k], "MPa");
}

void validate(const FractureToughness& toughness) {
  for (int k = 0; k < kToughnessKeys; ++k)
    require_positive(toughness.values[k], kToughnessNames[k], "N/mm");
}

}  // namespace si
