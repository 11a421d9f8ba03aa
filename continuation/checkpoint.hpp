// Checkpoints: what a resume needs (the branch so far and the run's State), as JSON with every
// double kept exactly (docs/theory/continuation.md, "Checkpoint format"). Problems that change
// their size in Problem::adapt must restore their own state (e.g. the contact candidate set)
// before resuming; the library checks only that the sizes agree.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "continuation/settings.hpp"
#include "continuation/state.hpp"

namespace si::cont {

struct Checkpoint {
  Method method = Method::kPseudoArclength;
  Branch branch;
  State state;
  // Settings::checkpoint_attachment's value when it was written; null when there was none.
  nlohmann::json attachment;
};

// Writes `path` atomically: to "<path>.tmp" first, then renamed over `path`, so a run killed
// while writing leaves the previous checkpoint intact. Throws std::runtime_error on I/O errors.
// With points_x = false the branch's points and events are written without x (see
// Settings::checkpoint_keeps_x); the state keeps its x in any case.
void save_checkpoint(const std::string& path, const Checkpoint& checkpoint, bool points_x = true);

// Throws std::runtime_error naming the file when it cannot be read or is not a checkpoint.
Checkpoint load_checkpoint(const std::string& path);

}  // namespace si::cont
