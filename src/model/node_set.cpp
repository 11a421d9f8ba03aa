#include "model/node_set.hpp"

#include "core/error.hpp"

namespace si {

const std::vector<int>& find_node_set(const Mesh& mesh, const std::string& name,
                                      const std::string& used_by) {
  const auto it = mesh.node_sets.find(name);
  if (it == mesh.node_sets.end()) {
    std::string available;
    for (const auto& [set_name, nodes] : mesh.node_sets)
      available += (available.empty() ? "" : ", ") + set_name;
    if (available.empty()) available = "none";
    throw_input(
        used_by + ": unknown node set '" + name + "' (available node sets: " + available + ")",
        Where{"", "node_set", name, 0});
  }
  for (int node : it->second)
    if (node < 0 || node >= mesh.num_nodes())
      throw_input(used_by + ": node set '" + name + "' holds node " + std::to_string(node) +
                      ", which is not in the mesh (" + std::to_string(mesh.num_nodes()) + " nodes)",
                  Where{"", "node_set", name, 0});
  return it->second;
}

}  // namespace si
