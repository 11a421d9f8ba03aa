// The output directory of a run: made (with its parents) and checked once the input is valid and
// before the run starts, so that a long run cannot be lost to a bad directory at the end.
#pragma once

#include <filesystem>

#include "core/error.hpp"

namespace si {

// Throws an input error at `where` (the case's output.dir or the command line's --out) if the
// directory cannot be made or is not a directory.
void prepare_output_directory(const std::filesystem::path& dir, const Where& where);

}  // namespace si
