// The case file's spellings of the rooms' enums that also appear in the results (docs/case-file.md,
// docs/results.md): one table each, read by io/case_file.cpp and written by the result writers,
// so that a name is spelt once.
#pragma once

#include <string>

#include "analysis/contact_spec.hpp"
#include "io/yaml_reader.hpp"
#include "shell/kinematics.hpp"

namespace si {

// none, hertz, yang_sun, vam, anisotropic
const Choices<LocalContactModel>& local_contact_spellings();
// local: anisotropic's support (half_space, bonded, frictionless, plate) and plies (homogenised,
// resolved)
const Choices<LocalSupport>& local_support_spellings();
const Choices<LocalPlies>& local_plies_spellings();
const Choices<Kinematics>& kinematics_spellings();  // linear, nonlinear

// The spelling of `value` in `choices` (the first, if several spell it).
template <class E>
const std::string& spelling(const Choices<E>& choices, E value) {
  for (const auto& c : choices)
    if (c.second == value) return c.first;
  static const std::string unknown = "?";
  return unknown;
}

}  // namespace si
