// The case file's spellings of the rooms' enums that also appear in the results (docs/case-file.md,
// docs/results.md): one table each, read by io/case_file.cpp and written by the result writers,
// so that a name is spelt once.
#pragma once

#include <string>

#include "analysis/contact_spec.hpp"
#include "analysis/damage_spec.hpp"
#include "analysis/path_spec.hpp"
#include "damage/impact_energy.hpp"
#include "damage/through_thickness_failure.hpp"
#include "io/yaml_reader.hpp"
#include "shell/kinematics.hpp"

namespace si {

// none, hertz, yang_sun, vam, anisotropic
const Choices<LocalContactModel>& local_contact_spellings();
// local: anisotropic's support (half_space, bonded, frictionless, plate) and plies (homogenised,
// resolved)
const Choices<LocalSupport>& local_support_spellings();
const Choices<LocalPlies>& local_plies_spellings();
const Choices<Kinematics>& kinematics_spellings();   // linear, nonlinear
const Choices<bool>& boolean_spellings();            // false, true
const Choices<PathMethod>& path_method_spellings();  // natural, pseudo_arclength
// Damage onset (docs/case-file.md `damage`, docs/results.md).
const Choices<Criterion>& criterion_spellings();      // max_stress, tsai_wu, hashin, delamination
const Choices<StressRecovery>& recovery_spellings();  // first_order, refined
const Choices<FacePressure>& face_pressure_spellings();                   // hertz, nodal
const Choices<EffectiveBendingStiffness>& bending_stiffness_spellings();  // olsson, geometric_mean
const Choices<FailureMode>& failure_mode_spellings();      // fibre_tension, ..., delamination
const Choices<PlyPosition>& ply_position_spellings();      // bottom, middle, top
const Choices<EnergyOutcome>& energy_outcome_spellings();  // reached, beyond_path

// The spelling of `value` in `choices` (the first, if several spell it).
template <class E>
const std::string& spelling(const Choices<E>& choices, E value) {
  for (const auto& c : choices)
    if (c.second == value) return c.first;
  static const std::string unknown = "?";
  return unknown;
}

}  // namespace si
