// What the MSH 4.1 and 2.2 parsers (gmsh_msh41.cpp, gmsh_msh22.cpp) hand to the reader
// (gmsh_reader.cpp): nodes and 4-node quadrangles by their Gmsh tags, and the physical groups
// as node sets (every dimension) and element sets (surfaces). Internal to the Gmsh reader.
#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/linalg.hpp"
#include "model/msh_scanner.hpp"

namespace si {

// A Gmsh element type ("elm-type" of the MSH format documentation); num_nodes = 0 when this
// reader does not know the type.
struct GmshElementType {
  int dim = 0;
  int num_nodes = 0;
  const char* name = "";
};
GmshElementType gmsh_element_type(long long type);

// Gmsh's linear quadrangle, the only element a shell mesh may contain.
constexpr long long kGmshQuad4 = 3;

// Refuses, naming the element and saying what to do, every element a shell mesh cannot hold:
// unknown types, triangles, higher-order quadrangles and volume elements.
void check_shell_element_type(const MshScanner& in, long long type, long long tag);

struct GmshContent {
  bool binary = false;
  int size_bytes = 8;  // of a binary "size_t" ($MeshFormat data-size)
  std::map<std::pair<int, int>, std::string> physical_names;  // (dim, physical tag) -> name
  std::vector<long long> node_tags;
  std::vector<Vector3d> node_positions;
  std::vector<std::array<long long, 4>> quads;  // node tags
  std::vector<long long> quad_tags;
  std::vector<long long> quad_positions;                    // line (text) or byte (binary)
  std::map<std::string, std::vector<long long>> node_sets;  // group name -> node tags
  std::map<std::string, std::vector<int>> element_sets;     // surface group -> quad indices

  // "element 12 (line 66)" or "element 12 (byte 4711)", the way messages name a quadrangle.
  std::string describe_quad(int quad) const;

  // The group's name, or "physical_<dim>_<tag>" when $PhysicalNames does not name it.
  std::string group_name(int dim, int physical_tag) const;

  // Adds the nodes of an element of dimension `dim` to the node sets of its physical groups,
  // and a quadrangle (quad >= 0) to their element sets.
  void add_to_groups(int dim, const std::vector<int>& physical_tags, const long long* nodes,
                     int num_nodes, int quad);
};

// The sections after $MeshFormat of a version 4.1 file (text or binary) and of a version 2.2
// text file.
void read_msh41_sections(MshScanner& in, GmshContent& out);
void read_msh22_sections(MshScanner& in, GmshContent& out);

// $PhysicalNames (text in every version).
void read_physical_names(MshScanner& in, GmshContent& out);

}  // namespace si
