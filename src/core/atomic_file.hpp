// Results are written whole or not at all: content goes to a temporary file beside the target,
// which is renamed over it only once complete. A run that fails never leaves a half-written file.
#pragma once

#include <string>

namespace si {

// Creates missing parent directories. Throws an input si::Error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace si
