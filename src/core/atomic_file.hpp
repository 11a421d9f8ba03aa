// Results are written whole or not at all, and survive a crash once written: content goes to a
// temporary file beside the target, which is flushed to disk (fsync) and then renamed over the
// target, and the directory is synced so that the rename itself is durable (a rename alone may
// reach the disk before the file's data: after a power cut the target could be empty). A run
// that fails never leaves a half-written file. The one implementation for every file the
// toolkit writes (results, VTU, checkpoints: the continuation library receives it as its
// checkpoint writer).
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace si {

// Creates missing parent directories. Throws an input si::Error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& content);

// The same, for content written by `write` to a stream (large files, e.g. VTU, are not first
// built as one string).
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace si
