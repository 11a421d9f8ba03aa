// MSH 2.2 text sections (the legacy format that meshio's `gmsh22` writes): $Nodes lists
// "tag x y z", $Elements lists "tag type number-of-tags tags... nodes...", whose first tag is the
// physical group and the second the geometric entity.
#include <vector>

#include "model/gmsh_content.hpp"

namespace si {
namespace {

void read_nodes(MshScanner& in, GmshContent& out) {
  const std::size_t n = in.count("the number of nodes", 8);
  out.node_tags.reserve(n);
  out.node_positions.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    out.node_tags.push_back(in.integer("a node tag"));
    Vector3d p;
    for (int c = 0; c < 3; ++c) p[c] = in.real("a node coordinate");
    if (!p.allFinite())
      in.fail("node " + std::to_string(out.node_tags.back()) + " has a non-finite coordinate");
    out.node_positions.push_back(p);
  }
  in.expect("$EndNodes");
}

void read_elements(MshScanner& in, GmshContent& out) {
  const std::size_t n = in.count("the number of elements", 8);
  long long nodes[10];
  for (std::size_t k = 0; k < n; ++k) {
    const long long tag = in.integer("an element tag");
    const long long location = in.location();
    const long long type = in.integer("an element type");
    check_shell_element_type(in, type, tag);
    const GmshElementType info = gmsh_element_type(type);
    const std::size_t num_tags = in.count("the number of element tags", 2);
    std::vector<int> groups;
    for (std::size_t t = 0; t < num_tags; ++t) {
      const long long value = in.integer("an element tag");
      if (t == 0 && value != 0) groups.push_back(static_cast<int>(value));
    }
    for (int a = 0; a < info.num_nodes; ++a) nodes[a] = in.integer("a node tag of an element");
    int quad = -1;
    if (type == kGmshQuad4) {
      quad = static_cast<int>(out.quads.size());
      out.quads.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
      out.quad_tags.push_back(tag);
      out.quad_positions.push_back(location);
    }
    out.add_to_groups(info.dim, groups, nodes, info.num_nodes, quad);
  }
  in.expect("$EndElements");
}

}  // namespace

void read_msh22_sections(MshScanner& in, GmshContent& out) {
  bool have_nodes = false, have_elements = false;
  while (!in.at_end()) {
    const std::string section(in.token("a section"));
    if (section == "$PhysicalNames") {
      read_physical_names(in, out);
    } else if (section == "$Nodes") {
      if (have_nodes) in.fail("a second $Nodes section");
      read_nodes(in, out);
      have_nodes = true;
    } else if (section == "$Elements") {
      if (!have_nodes) in.fail("$Elements comes before $Nodes");
      if (have_elements) in.fail("a second $Elements section");
      read_elements(in, out);
      have_elements = true;
    } else if (section.size() > 1 && section[0] == '$') {
      in.skip_past("$End" + section.substr(1));
    } else {
      in.fail("expected a section such as $Nodes", section);
    }
  }
  if (!have_nodes) in.fail("the file has no $Nodes section (truncated file?)");
  if (!have_elements) in.fail("the file has no $Elements section (truncated file?)");
}

}  // namespace si
