#include "model/named_loads.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "model/node_set.hpp"

namespace si {
namespace {

const std::vector<int>& node_set(const Mesh& mesh, const NamedLoadSpec& spec) {
  try {
    return find_node_set(mesh, spec.on, "load");
  } catch (const Error& e) {
    throw Error(e.kind(), e.reason(), spec.where);
  }
}

bool in_set(const std::vector<int>& sorted, int node) {
  return std::binary_search(sorted.begin(), sorted.end(), node);
}

int nearest_node(const Mesh& mesh, const Vector3d& at) {
  int best = 0;
  for (int n = 1; n < mesh.num_nodes(); ++n)
    if ((mesh.nodes[n] - at).squaredNorm() < (mesh.nodes[best] - at).squaredNorm()) best = n;
  return best;
}

void add_point(Mesh& mesh, const NamedLoadSpec& spec, std::size_t index,
               const std::vector<const std::vector<int>*>& planes, Loads& loads) {
  std::string name = spec.on;
  if (spec.at) {
    name = "loads[" + std::to_string(index) + "]";
    set_node_set(mesh, name, {nearest_node(mesh, *spec.at)});
  }
  for (int node : node_set(mesh, NamedLoadSpec{spec.type, name, {}, {}, 0, false, spec.where})) {
    double share = 1;
    for (const auto* plane : planes)
      if (in_set(*plane, node)) share /= 2;
    const std::string single = name + "#" + std::to_string(node);
    set_node_set(mesh, single, {node});
    loads.points.push_back({single, spec.vector * share, true});
  }
}

void add_edge(const Mesh& mesh, const NamedLoadSpec& spec,
              const std::vector<const std::vector<int>*>& planes, Loads& loads) {
  const std::vector<int>& nodes = node_set(mesh, spec);
  std::set<std::pair<int, int>> sides;
  for (const auto& el : mesh.elements)
    for (int k = 0; k < 4; ++k) {
      const int a = el[k], b = el[(k + 1) % 4];
      if (in_set(nodes, a) && in_set(nodes, b)) sides.insert({std::min(a, b), std::max(a, b)});
    }
  if (sides.empty())
    throw_input("an edge load needs a line of nodes, and no element side has both its nodes in '" +
                    spec.on + "'",
                spec.where);
  for (const auto& [a, b] : sides) {
    for (const auto* plane : planes)
      if (in_set(*plane, a) && in_set(*plane, b))
        throw_input(
            "an edge load on a symmetry plane of a quarter model is not supported (its "
            "share of the load is ambiguous); model the full shell",
            spec.where);
    loads.lines.push_back({{a, b}, spec.vector});
  }
}

std::vector<int> pressure_elements(const Mesh& mesh, const NamedLoadSpec& spec) {
  if (spec.on.empty()) return {};
  const auto it = mesh.element_sets.find(spec.on);
  if (it != mesh.element_sets.end()) return it->second;
  const std::vector<int>& nodes = node_set(mesh, spec);
  std::vector<int> elements;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto& el = mesh.elements[e];
    if (std::all_of(el.begin(), el.end(), [&](int n) { return in_set(nodes, n); }))
      elements.push_back(e);
  }
  if (elements.empty())
    throw_input("a pressure needs elements, and no element has all its nodes in '" + spec.on + "'",
                spec.where);
  return elements;
}

}  // namespace

void add_named_loads(Mesh& mesh, const std::vector<NamedLoadSpec>& specs,
                     const std::vector<std::string>& symmetry_sets, Loads& loads) {
  std::vector<const std::vector<int>*> planes;
  for (const std::string& name : symmetry_sets)
    planes.push_back(&find_node_set(mesh, name, "symmetry plane"));
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const NamedLoadSpec& spec = specs[i];
    switch (spec.type) {
      case NamedLoadType::kPoint:
        add_point(mesh, spec, i, planes, loads);
        break;
      case NamedLoadType::kEdge:
        add_edge(mesh, spec, planes, loads);
        break;
      case NamedLoadType::kPressure:
        // loads.hpp: a positive PressureLoad pushes towards the director side.
        loads.pressures.push_back({-spec.pressure, spec.follower, pressure_elements(mesh, spec)});
        break;
    }
  }
}

}  // namespace si
