// The case file's `damage:` section (docs/case-file.md) into the runs' DamageSpec
// (analysis/damage_spec.hpp). The strengths and the toughness the chosen criteria and the
// threshold read are checked here, against every ply's material, so that a case that cannot
// evaluate them is refused before anything is computed or written (the message names the
// material, the missing key and the criterion, at the line of the criterion).
#pragma once

#include <optional>

#include "analysis/damage_spec.hpp"
#include "io/yaml_reader.hpp"
#include "section/laminate.hpp"

namespace si {

// std::nullopt when the case has no `damage:` section.
std::optional<DamageSpec> read_damage(const MapReader& top, const Laminate& laminate);

}  // namespace si
