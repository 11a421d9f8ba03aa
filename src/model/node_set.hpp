// Looking up a named node set of a Mesh, with the error message every user of a node set needs.
#pragma once

#include <string>
#include <vector>

#include "model/mesh.hpp"

namespace si {

// The nodes of set `name`. Throws an input error that lists the mesh's sets if there is no such
// set; `used_by` (e.g. "support 2") says who asked, for the message.
const std::vector<int>& find_node_set(const Mesh& mesh, const std::string& name,
                                      const std::string& used_by);

}  // namespace si
