// Test support: writes a Mesh as a Gmsh MSH 4.1 text file, node tags = index + 1, element tags =
// index + 1, so that the reader gives back the same numbering. Each named node set becomes a
// physical group: a single node a physical point, a line of nodes the physical curve of the
// element sides whose two nodes are in the set. The whole surface is the physical surface
// "surface".
#pragma once

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "model/mesh.hpp"

namespace si::testing {

inline void write_msh41(const Mesh& mesh, const std::vector<std::string>& sets,
                        const std::string& path) {
  struct Group {
    std::string name;
    int dim;
    std::vector<std::vector<int>> elements;  // 1 node (points) or 2 (lines)
  };
  std::vector<Group> groups;
  for (const std::string& name : sets) {
    const std::vector<int>& nodes = mesh.node_sets.at(name);
    const std::set<int> in(nodes.begin(), nodes.end());
    Group g{name, nodes.size() == 1 ? 0 : 1, {}};
    if (g.dim == 0) {
      g.elements.push_back({nodes[0]});
    } else {
      std::set<std::pair<int, int>> sides;
      for (const auto& el : mesh.elements)
        for (int k = 0; k < 4; ++k) {
          const int a = el[k], b = el[(k + 1) % 4];
          if (in.count(a) && in.count(b)) sides.insert({std::min(a, b), std::max(a, b)});
        }
      for (const auto& [a, b] : sides) g.elements.push_back({a, b});
    }
    groups.push_back(g);
  }
  std::ostringstream os;
  os.precision(17);
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" << groups.size() + 1 << "\n";
  for (size_t k = 0; k < groups.size(); ++k)
    os << groups[k].dim << " " << k + 1 << " \"" << groups[k].name << "\"\n";
  os << "2 " << groups.size() + 1 << " \"surface\"\n$EndPhysicalNames\n";
  // One entity per group (tag k + 1 in its dimension) and one surface (tag 1).
  int points = 0, curves = 0;
  for (const auto& g : groups) (g.dim == 0 ? points : curves)++;
  os << "$Entities\n" << points << " " << curves << " 1 0\n";
  for (size_t k = 0; k < groups.size(); ++k)
    if (groups[k].dim == 0) os << k + 1 << " 0 0 0 1 " << k + 1 << "\n";
  for (size_t k = 0; k < groups.size(); ++k)
    if (groups[k].dim == 1) os << k + 1 << " 0 0 0 0 0 0 1 " << k + 1 << " 0\n";
  os << "1 0 0 0 0 0 0 1 " << groups.size() + 1 << " 0\n$EndEntities\n";
  const int nn = mesh.num_nodes();
  os << "$Nodes\n1 " << nn << " 1 " << nn << "\n2 1 0 " << nn << "\n";
  for (int n = 0; n < nn; ++n) os << n + 1 << "\n";
  for (const Vector3d& p : mesh.nodes) os << p.x() << " " << p.y() << " " << p.z() << "\n";
  os << "$EndNodes\n";
  size_t total = mesh.elements.size();
  for (const auto& g : groups) total += g.elements.size();
  os << "$Elements\n" << groups.size() + 1 << " " << total << " 1 " << total << "\n";
  size_t tag = 1;
  os << "2 1 3 " << mesh.elements.size() << "\n";
  for (const auto& el : mesh.elements)
    os << tag++ << " " << el[0] + 1 << " " << el[1] + 1 << " " << el[2] + 1 << " " << el[3] + 1
       << "\n";
  for (size_t k = 0; k < groups.size(); ++k) {
    const auto& g = groups[k];
    os << g.dim << " " << k + 1 << " " << (g.dim == 0 ? 15 : 1) << " " << g.elements.size() << "\n";
    for (const auto& e : g.elements) {
      os << tag++;
      for (int n : e) os << " " << n + 1;
      os << "\n";
    }
  }
  os << "$EndElements\n";
  std::ofstream(path) << os.str();
}

}  // namespace si::testing
