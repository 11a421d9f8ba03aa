#include "model/gmsh_content.hpp"

namespace si {

GmshElementType gmsh_element_type(long long type) {
  switch (type) {
    case 1:
      return {1, 2, "2-node line"};
    case 2:
      return {2, 3, "3-node triangle"};
    case 3:
      return {2, 4, "4-node quadrangle"};
    case 4:
      return {3, 4, "4-node tetrahedron"};
    case 5:
      return {3, 8, "8-node hexahedron"};
    case 6:
      return {3, 6, "6-node prism"};
    case 7:
      return {3, 5, "5-node pyramid"};
    case 8:
      return {1, 3, "3-node line"};
    case 9:
      return {2, 6, "6-node triangle"};
    case 10:
      return {2, 9, "9-node quadrangle"};
    case 11:
      return {3, 10, "10-node tetrahedron"};
    case 15:
      return {0, 1, "1-node point"};
    case 16:
      return {2, 8, "8-node quadrangle"};
    case 20:
      return {2, 9, "9-node triangle"};
    case 21:
      return {2, 10, "10-node triangle"};
    case 26:
      return {1, 4, "4-node line"};
    case 27:
      return {1, 5, "5-node line"};
    case 28:
      return {1, 6, "6-node line"};
    default:
      return {0, 0, ""};
  }
}

void check_shell_element_type(const MshScanner& in, long long type, long long tag) {
  const GmshElementType info = gmsh_element_type(type);
  const std::string element = "element " + std::to_string(tag);
  if (info.num_nodes == 0)
    in.fail(element + " has the Gmsh element type " + std::to_string(type) +
                ", which a shell mesh cannot hold (4-node quadrangles, type 3, only)",
            std::to_string(type));
  if (info.dim == 3)
    in.fail(element + " is a " + info.name +
            " (a volume element): a shell mesh is a surface mesh of 4-node quadrangles; "
            "export the surface only (mesh it with `gmsh -2`)");
  if (info.dim != 2 || type == kGmshQuad4) return;
  if (info.num_nodes > 4 && (type == 10 || type == 16))
    in.fail(element + " is a " + info.name +
            ": only linear (4-node) quadrangles are supported; mesh with Mesh.ElementOrder = 1");
  in.fail(element + " is a " + info.name +
          ": shellindent's shell elements are 4-node quadrangles and there is no triangle "
          "shell; remesh with quadrangles (Gmsh: Recombine Surface{...}; or Mesh.RecombineAll = "
          "1, with Mesh.Algorithm = 8 for a quad-dominant mesh and "
          "Mesh.SubdivisionAlgorithm = 1 to split the remaining triangles; docs/case-file.md)");
}

std::string GmshContent::describe_quad(int quad) const {
  return "element " + std::to_string(quad_tags[quad]) + " (" + (binary ? "byte " : "line ") +
         std::to_string(quad_positions[quad]) + ")";
}

std::string GmshContent::group_name(int dim, int physical_tag) const {
  const auto it = physical_names.find({dim, physical_tag});
  if (it != physical_names.end()) return it->second;
  return "physical_" + std::to_string(dim) + "_" + std::to_string(physical_tag);
}

void GmshContent::add_to_groups(int dim, const std::vector<int>& physical_tags,
                                const long long* nodes, int num_nodes, int quad) {
  for (int p : physical_tags) {
    const std::string name = group_name(dim, p);
    auto& set = node_sets[name];
    set.insert(set.end(), nodes, nodes + num_nodes);
    if (quad >= 0) element_sets[name].push_back(quad);
  }
}

void read_physical_names(MshScanner& in, GmshContent& out) {
  const std::size_t n = in.count("the number of physical names", 6);
  for (std::size_t k = 0; k < n; ++k) {
    const int dim = static_cast<int>(in.integer("a physical group dimension"));
    const int tag = static_cast<int>(in.integer("a physical group tag"));
    std::string name = in.rest_of_line("a physical group name");
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
      name = name.substr(1, name.size() - 2);
    if (dim < 0 || dim > 3)
      in.fail("a physical group dimension must be 0 to 3", std::to_string(dim));
    out.physical_names[{dim, tag}] = name;
  }
  in.expect("$EndPhysicalNames");
}

}  // namespace si
