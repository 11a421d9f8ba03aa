// The `damage` object of path.json and the onset fields of events.json (docs/results.md): the
// onsets with their mode, ply or interface and position, the delamination threshold with its
// inputs, the depths at the impact energies (analysis/damage_results.hpp).
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/indentation_run.hpp"

namespace si {

// criterion, mode, ply (1-based, bottom ply 1) or interface (between plies k and k+1), position,
// x3, node and the depth, force and work of an onset.
nlohmann::json onset_json(const DamageOnset& onset);
nlohmann::json damage_json(const IndentationSetup& setup, const PathResult& result);

}  // namespace si
