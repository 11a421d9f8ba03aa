#include "model/named_loads.hpp"

#include <algorithm>
#include <map>
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

// loads.hpp NodalMoment: a moment acts on the two rotation dofs only; a drilling component (along
// the node's director) would be dropped silently, so it is refused here, naming the entry.
void check_no_drilling(const Mesh& mesh, const Vector3d& moment, int node, const Where& where) {
  if (is_drilling(moment, mesh.directors[node]))
    throw_input("the moment has a component along the shell normal at node " +
                    std::to_string(node) +
                    " (a drilling moment, which the shell has no rotation to take); give only "
                    "components in the shell's tangent plane",
                where);
}

// A point force or a nodal moment: the same sets, `at` and symmetry shares.
void add_point(Mesh& mesh, const NamedLoadSpec& spec, std::size_t index,
               const std::vector<const std::vector<int>*>& planes, Loads& loads) {
  std::string name = spec.on;
  if (spec.at) {
    name = "loads[" + std::to_string(index) + "]";
    set_node_set(mesh, name, {nearest_node(mesh, *spec.at)});
  }
  NamedLoadSpec named = spec;
  named.on = name;
  for (int node : node_set(mesh, named)) {
    double share = 1;
    for (const auto* plane : planes)
      if (in_set(*plane, node)) share /= 2;
    const std::string single = name + "#" + std::to_string(node);
    set_node_set(mesh, single, {node});
    if (spec.type == NamedLoadType::kMoment) {
      check_no_drilling(mesh, spec.vector, node, spec.where);
      loads.moments.push_back({single, spec.vector * share, true});
    } else
      loads.points.push_back({single, spec.vector * share, true});
  }
}

// The consistent nodal moments of a constant moment per length on the element sides: half of
// m L to each end of a side of reference length L.
void add_edge_moments(Mesh& mesh, const NamedLoadSpec& spec,
                      const std::set<std::pair<int, int>>& sides, Loads& loads) {
  std::map<int, Vector3d> at_node;
  for (const auto& [a, b] : sides) {
    const Vector3d half = 0.5 * (mesh.nodes[b] - mesh.nodes[a]).norm() * spec.moment;
    for (int n : {a, b}) at_node.try_emplace(n, Vector3d::Zero()).first->second += half;
  }
  for (const auto& [node, moment] : at_node) {
    check_no_drilling(mesh, moment, node, spec.where);
    const std::string single = spec.on + "#" + std::to_string(node);
    set_node_set(mesh, single, {node});
    loads.moments.push_back({single, moment, true});
  }
}

void add_edge(Mesh& mesh, const NamedLoadSpec& spec,
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
    if (!spec.vector.isZero()) loads.lines.push_back({{a, b}, spec.vector});
  }
  if (!spec.moment.isZero()) add_edge_moments(mesh, spec, sides, loads);
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
      case NamedLoadType::kMoment:
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
