// The damage columns of sweep.csv / sweep.json (docs/results.md "Damage"): per case, from its
// path.json's `damage` object, the first onset of each criterion (depth, force, work, mode), the
// Davies-Zhang threshold with the depth where the path reaches it, and the depth and force at
// each impact energy.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/study_file.hpp"

namespace si {

// The columns the study's cases ask for (none without a `damage:` section), in a fixed order.
std::vector<std::string> damage_columns(const std::vector<StudyCase>& cases);

// Adds a case's values of those columns to its row (absent ones stay empty).
void summarize_damage(const nlohmann::json& path, nlohmann::json& row);

}  // namespace si
