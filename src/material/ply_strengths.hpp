// Strengths of a ply and the interlaminar fracture toughness of its interfaces: what the damage
// onset criteria (src/damage/) and the delamination threshold need beside the elastic constants.
// Every value is optional: a material may carry only what a given criterion asks for, and a
// criterion that needs a missing value is refused naming the material and the key
// (damage/criterion_strengths.hpp).
//
// Axes as in material.hpp: 1 = fibre, 2 = in-plane transverse, 3 = through-thickness.
// Strengths are magnitudes in MPa (compressive strengths X_C, Y_C, Z_C are positive numbers);
// toughness is energy per unit crack area in N/mm (= kJ/m^2).
#pragma once

#include <array>
#include <optional>

namespace si {

enum class StrengthKey {
  kXT,   // tension along the fibre
  kXC,   // compression along the fibre
  kYT,   // in-plane transverse tension
  kYC,   // in-plane transverse compression
  kZT,   // through-thickness tension (interlaminar normal strength)
  kZC,   // through-thickness compression
  kS12,  // in-plane shear
  kS13,  // interlaminar shear in the fibre direction (longitudinal-normal plane)
  kS23,  // transverse shear (transverse-normal plane)
};
inline constexpr int kStrengthKeys = 9;

enum class ToughnessKey {
  kGIc,   // mode I (opening) interlaminar fracture toughness
  kGIIc,  // mode II (sliding shear) interlaminar fracture toughness
};
inline constexpr int kToughnessKeys = 2;

// The key as users write it in case files and as errors name it: "X_T", ..., "G_IIc".
const char* key_name(StrengthKey key);
const char* key_name(ToughnessKey key);

struct PlyStrengths {
  std::array<std::optional<double>, kStrengthKeys> values;  // MPa, indexed by StrengthKey

  std::optional<double> get(StrengthKey key) const { return values[static_cast<int>(key)]; }
  void set(StrengthKey key, double value) { values[static_cast<int>(key)] = value; }
  bool empty() const;
};

struct FractureToughness {
  std::array<std::optional<double>, kToughnessKeys> values;  // N/mm, indexed by ToughnessKey

  std::optional<double> get(ToughnessKey key) const { return values[static_cast<int>(key)]; }
  void set(ToughnessKey key, double value) { values[static_cast<int>(key)] = value; }
  bool empty() const;
};

// Every value present must be positive and finite: throws an input si::Error whose key names the
// offending value ("Y_T") otherwise (a zero or negative strength has no meaning and would make
// the failure indices infinite or change sign).
void validate(const PlyStrengths& strengths);
void validate(const FractureToughness& toughness);

}  // namespace si
