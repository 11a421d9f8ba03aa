// Named materials with a stated source, so that case files and studies can say
// "material: paper-carbon-epoxy" instead of repeating constants. Each entry's source is cited
// beside it in material_library.cpp.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "material/material.hpp"

namespace si {

// The library's names, in a fixed order (for --help and error messages).
std::vector<std::string> library_material_names();

// The named material. Throws an input si::Error listing the known names when `name` is unknown.
Material library_material(std::string_view name);

}  // namespace si
