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

// The checkpoint as JSON text. With points_x = false the branch's points and events are written
// without x (see Settings::checkpoint_keeps_x); the state keeps its x in any case.
std::string checkpoint_text(const Checkpoint& checkpoint, bool points_x = true);

// Hands checkpoint_text to `write` for `path`. The library does no file I/O of its own: the
// writer (Settings::checkpoint_writer) must replace the file atomically, so that a run killed
// while writing leaves the previous checkpoint intact.
void save_checkpoint(const std::string& path, const Checkpoint& checkpoint, bool points_x,
                     const FileWriter& write);

// Throws std::runtime_error naming the file when it cannot be read or is not a checkpoint.
Checkpoint load_checkpoint(const std::string& path);

}  // namespace si::cont
