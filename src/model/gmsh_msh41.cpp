// MSH 4.1 sections, text and binary (https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format):
// the same fields in the same order; binary files store "int" as 4 bytes, "size_t" as the data
// size of $MeshFormat and reals as 8-byte doubles, in the writer's byte order. Physical groups
// sit on the geometric entities ($Entities), so an element belongs to the groups of its entity.
#include <map>
#include <utility>
#include <vector>

#include "model/gmsh_content.hpp"

namespace si {
namespace {

using EntityKey = std::pair<int, int>;  // (dimension, entity tag)

// The fields of an MSH 4.1 file, read as text or binary.
class Fields {
 public:
  Fields(MshScanner& in, bool binary, int size_bytes)
      : in_(in), binary_(binary), size_bytes_(size_bytes) {}

  bool binary() const { return binary_; }
  int size_bytes() const { return binary_ ? size_bytes_ : 2; }  // least bytes of a size_t
  int int_bytes() const { return binary_ ? 4 : 2; }
  int real_bytes() const { return binary_ ? 8 : 2; }

  std::size_t count(const char* what, std::size_t bytes_each) {
    return binary_ ? in_.binary_count(what, bytes_each) : in_.count(what, bytes_each);
  }
  long long size(const char* what) {
    return binary_ ? static_cast<long long>(in_.binary_size(what)) : in_.integer(what);
  }
  int integer(const char* what) {
    return binary_ ? in_.binary<int>(what) : static_cast<int>(in_.integer(what));
  }
  double real(const char* what) { return binary_ ? in_.binary<double>(what) : in_.real(what); }

 private:
  MshScanner& in_;
  bool binary_;
  int size_bytes_;
};

void read_entities(MshScanner& in, Fields& f, std::map<EntityKey, std::vector<int>>& physicals) {
  std::size_t counts[4];
  for (std::size_t& c : counts) c = f.count("the number of entities", 3 * f.int_bytes());
  for (int dim = 0; dim < 4; ++dim) {
    for (std::size_t k = 0; k < counts[dim]; ++k) {
      const int tag = f.integer("an entity tag");
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) f.real("an entity coordinate");
      const std::size_t num_physicals = f.count("the number of physical tags", f.int_bytes());
      auto& tags = physicals[{dim, tag}];
      for (std::size_t p = 0; p < num_physicals; ++p) tags.push_back(f.integer("a physical tag"));
      if (dim == 0) continue;
      const std::size_t num_bounding = f.count("the number of bounding entities", f.int_bytes());
      for (std::size_t b = 0; b < num_bounding; ++b) f.integer("a bounding entity tag");
    }
  }
  in.expect("$EndEntities");
}

void read_nodes(MshScanner& in, Fields& f, GmshContent& out) {
  const std::size_t num_blocks = f.count("the number of node blocks", 3 * f.int_bytes());
  const std::size_t total = f.count("the number of nodes", f.size_bytes() + 3 * f.real_bytes());
  f.size("the smallest node tag");
  f.size("the largest node tag");
  out.node_tags.reserve(total);
  out.node_positions.reserve(total);
  for (std::size_t b = 0; b < num_blocks; ++b) {
    const int dim = f.integer("an entity dimension");
    f.integer("an entity tag");
    const int parametric = f.integer("the parametric flag");
    if (dim < 0 || dim > 3) in.fail("an entity dimension must be 0 to 3", std::to_string(dim));
    const int extra = parametric != 0 ? dim : 0;
    const std::size_t n =
        f.count("the number of nodes in a block", f.size_bytes() + (3 + extra) * f.real_bytes());
    const std::size_t first = out.node_tags.size();
    for (std::size_t k = 0; k < n; ++k) out.node_tags.push_back(f.size("a node tag"));
    for (std::size_t k = 0; k < n; ++k) {
      Vector3d p;
      for (int c = 0; c < 3; ++c) p[c] = f.real("a node coordinate");
      for (int u = 0; u < extra; ++u) f.real("a parametric coordinate");
      if (!p.allFinite())
        in.fail("node " + std::to_string(out.node_tags[first + k]) +
                " has a non-finite coordinate");
      out.node_positions.push_back(p);
    }
  }
  if (out.node_tags.size() != total)
    in.fail("$Nodes announces " + std::to_string(total) + " nodes but its blocks hold " +
            std::to_string(out.node_tags.size()));
  in.expect("$EndNodes");
}

void read_elements(MshScanner& in, Fields& f,
                   const std::map<EntityKey, std::vector<int>>& physicals, GmshContent& out) {
  const std::size_t num_blocks = f.count("the number of element blocks", 3 * f.int_bytes());
  f.count("the number of elements", 2 * f.size_bytes());
  f.size("the smallest element tag");
  f.size("the largest element tag");
  const std::vector<int> none;
  for (std::size_t b = 0; b < num_blocks; ++b) {
    const int dim = f.integer("an entity dimension");
    const int entity = f.integer("an entity tag");
    const int type = f.integer("an element type");
    const GmshElementType info = gmsh_element_type(type);
    // At least a tag and a node each: the element type is checked at the first element.
    const std::size_t n = f.count("the number of elements in a block", 2 * f.size_bytes());
    const auto phys = physicals.find({dim, entity});
    const std::vector<int>& groups = phys == physicals.end() ? none : phys->second;
    long long nodes[10];
    for (std::size_t k = 0; k < n; ++k) {
      const long long tag = f.size("an element tag");
      const long long location = in.location();
      if (info.dim != dim && info.num_nodes > 0)
        in.fail("element " + std::to_string(tag) + " is a " + info.name +
                " in a block of dimension " + std::to_string(dim));
      check_shell_element_type(in, type, tag);
      for (int a = 0; a < info.num_nodes; ++a) nodes[a] = f.size("a node tag of an element");
      int quad = -1;
      if (type == kGmshQuad4) {
        quad = static_cast<int>(out.quads.size());
        out.quads.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
        out.quad_tags.push_back(tag);
        out.quad_positions.push_back(location);
      }
      out.add_to_groups(dim, groups, nodes, info.num_nodes, quad);
    }
  }
  in.expect("$EndElements");
}

}  // namespace

void read_msh41_sections(MshScanner& in, GmshContent& out) {
  Fields f(in, out.binary, out.size_bytes);
  std::map<EntityKey, std::vector<int>> physicals;
  bool have_nodes = false, have_elements = false, have_entities = false;
  while (!in.at_end()) {
    const std::string section(in.token("a section"));
    const bool data = section == "$Entities" || section == "$Nodes" || section == "$Elements";
    if (data && f.binary()) in.skip_line_break();  // binary data starts after the header line
    if (section == "$PhysicalNames") {
      read_physical_names(in, out);
    } else if (section == "$Entities") {
      if (have_entities) in.fail("a second $Entities section");
      read_entities(in, f, physicals);
      have_entities = true;
    } else if (section == "$Nodes") {
      if (have_nodes) in.fail("a second $Nodes section");
      read_nodes(in, f, out);
      have_nodes = true;
    } else if (section == "$Elements") {
      if (!have_nodes) in.fail("$Elements comes before $Nodes");
      if (have_elements) in.fail("a second $Elements section");
      read_elements(in, f, physicals, out);
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
