// The case file's `supports:` and `loads:` lists (docs/case-file.md): supports and loads on
// named sets of the mesh. The set names are checked against the mesh when the model is built
// (analysis/shell_model.cpp); here each entry's keys, values and units, and conflicting
// supports on one set.
#pragma once

#include <vector>

#include "io/yaml_reader.hpp"
#include "model/named_loads.hpp"
#include "model/named_supports.hpp"

namespace si {

// Empty when the case has no `supports:`.
std::vector<NamedSupportSpec> read_supports(const MapReader& top);

// Empty when the case has no `loads:`.
std::vector<NamedLoadSpec> read_named_loads(const MapReader& top);

}  // namespace si
