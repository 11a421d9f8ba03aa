#include "model/gmsh_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "model/mesh_quality.hpp"

namespace si {
namespace {

// Whitespace-separated tokens of a text file, each with its 1-based line number.
class TokenStream {
 public:
  explicit TokenStream(const std::string& path) : path_(path) {
    std::ifstream in(path);
    if (!in) throw_input("cannot open the Gmsh mesh file", {path, "", "", 0});
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines_.push_back(line);
    }
  }

  bool at_end() {
    skip_space();
    return row_ >= lines_.size();
  }
  int line() const { return static_cast<int>(std::min(row_, lines_.size())) + 1; }

  [[noreturn]] void fail(const std::string& reason, const std::string& value = "") const {
    throw_input(reason, {path_, "", value, line()});
  }

  std::string token(const std::string& what) {
    if (at_end()) fail("the file ends early: expected " + what + " (truncated file?)");
    const std::string& text = lines_[row_];
    const size_t end = text.find_first_of(" \t", col_);
    const size_t stop = end == std::string::npos ? text.size() : end;
    std::string t = text.substr(col_, stop - col_);
    col_ = stop;
    return t;
  }

  // The rest of the current line, trimmed (for quoted names that contain spaces).
  std::string rest_of_line(const std::string& what) {
    if (at_end()) fail("the file ends early: expected " + what + " (truncated file?)");
    std::string t = lines_[row_].substr(col_);
    col_ = lines_[row_].size();
    const size_t last = t.find_last_not_of(" \t");
    return t.substr(0, last + 1);
  }

  long long integer(const std::string& what) {
    const std::string t = token(what);
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(t.c_str(), &end, 10);
    if (t.empty() || *end != '\0' || errno != 0) fail("expected an integer (" + what + ")", t);
    return value;
  }

  int count(const std::string& what) {
    const long long value = integer(what);
    if (value < 0 || value > 2000000000)
      fail("expected a count (" + what + ")", std::to_string(value));
    return static_cast<int>(value);
  }

  double real(const std::string& what) {
    const std::string t = token(what);
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || errno != 0) fail("expected a number (" + what + ")", t);
    return value;
  }

  void expect(const std::string& wanted) {
    const std::string t = token(wanted);
    if (t != wanted) fail("expected " + wanted, t);
  }

  // Skips to just after `end_marker` (for sections this reader does not use).
  void skip_to(const std::string& end_marker) {
    while (token(end_marker) != end_marker) {
    }
  }

 private:
  void skip_space() {
    while (row_ < lines_.size()) {
      const size_t next = lines_[row_].find_first_not_of(" \t", col_);
      if (next != std::string::npos) {
        col_ = next;
        return;
      }
      ++row_;
      col_ = 0;
    }
  }

  std::string path_;
  std::vector<std::string> lines_;
  size_t row_ = 0, col_ = 0;
};

struct GmshElementType {
  int dim;
  int num_nodes;
  const char* name;
};

// Gmsh element types (MSH format documentation, "elm-type") a surface mesh file may contain;
// num_nodes = 0 for a type this reader does not know.
GmshElementType element_type(long long type) {
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

using EntityKey = std::pair<int, int>;  // (dimension, tag)

struct MshContent {
  std::map<EntityKey, std::string> physical_names;  // (dim, physical tag) -> name
  std::map<EntityKey, std::vector<int>> physicals;  // entity -> its physical tags
  std::map<long long, Vector3d> nodes;              // Gmsh node tag -> position
  std::vector<std::array<long long, 4>> quads;      // node tags
  std::vector<long long> quad_tags;                 // Gmsh element tags
  std::vector<int> quad_lines;
  std::map<std::string, std::vector<long long>> set_tags;  // node set -> node tags
};

void read_format(TokenStream& in) {
  const std::string version = in.token("the MSH version");
  if (version != "4.1") in.fail("MSH " + version + " is not supported, export as 4.1");
  const long long file_type = in.integer("the file type");
  if (file_type != 0) in.fail("binary MSH files are not supported, export as ASCII 4.1");
  in.real("the data size");
  in.expect("$EndMeshFormat");
}

void read_physical_names(TokenStream& in, MshContent& msh) {
  const int n = in.count("the number of physical names");
  for (int k = 0; k < n; ++k) {
    const int dim = static_cast<int>(in.integer("a physical group dimension"));
    const int tag = static_cast<int>(in.integer("a physical group tag"));
    std::string name = in.rest_of_line("a physical group name");
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') {
      name = name.substr(1, name.size() - 2);
    }
    msh.physical_names[{dim, tag}] = name;
  }
  in.expect("$EndPhysicalNames");
}

void read_entities(TokenStream& in, MshContent& msh) {
  int counts[4];
  for (int& c : counts) c = in.count("the number of entities");
  for (int dim = 0; dim < 4; ++dim) {
    for (int k = 0; k < counts[dim]; ++k) {
      const int tag = static_cast<int>(in.integer("an entity tag"));
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) in.real("an entity coordinate");
      const int num_physicals = in.count("the number of physical tags");
      auto& tags = msh.physicals[{dim, tag}];
      for (int p = 0; p < num_physicals; ++p) {
        tags.push_back(static_cast<int>(in.integer("a physical tag")));
      }
      if (dim > 0) {
        const int num_bounding = in.count("the number of bounding entities");
        for (int b = 0; b < num_bounding; ++b) in.integer("a bounding entity tag");
      }
    }
  }
  in.expect("$EndEntities");
}

void read_nodes(TokenStream& in, MshContent& msh) {
  const int num_blocks = in.count("the number of node blocks");
  in.count("the number of nodes");
  in.integer("the smallest node tag");
  in.integer("the largest node tag");
  for (int b = 0; b < num_blocks; ++b) {
    const int dim = static_cast<int>(in.integer("an entity dimension"));
    in.integer("an entity tag");
    const long long parametric = in.integer("the parametric flag");
    const int n = in.count("the number of nodes in a block");
    std::vector<long long> tags(n);
    for (long long& tag : tags) tag = in.integer("a node tag");
    for (long long tag : tags) {
      Vector3d p;
      for (int c = 0; c < 3; ++c) p[c] = in.real("a node coordinate");
      for (int u = 0; u < (parametric ? dim : 0); ++u) in.real("a parametric coordinate");
      if (!msh.nodes.emplace(tag, p).second)
        in.fail("node tag " + std::to_string(tag) + " is defined twice");
    }
  }
  in.expect("$EndNodes");
}

void read_elements(TokenStream& in, MshContent& msh) {
  const int num_blocks = in.count("the number of element blocks");
  in.count("the number of elements");
  in.integer("the smallest element tag");
  in.integer("the largest element tag");
  for (int b = 0; b < num_blocks; ++b) {
    const int dim = static_cast<int>(in.integer("an entity dimension"));
    const int entity = static_cast<int>(in.integer("an entity tag"));
    const long long type = in.integer("an element type");
    const int n = in.count("the number of elements in a block");
    const GmshElementType info = element_type(type);
    if (info.num_nodes == 0) in.fail("unsupported Gmsh element type", std::to_string(type));
    for (int k = 0; k < n; ++k) {
      const long long tag = in.integer("an element tag");
      if (info.dim == 3) {
        in.fail("only quadrilateral surface meshes are supported; element " + std::to_string(tag) +
                " is a " + info.name + " (a volume element)");
      }
      if (info.dim == 2 && type != 3) {
        in.fail("only quadrilateral surface meshes are supported; element " + std::to_string(tag) +
                " is a " + info.name);
      }
      const int line = in.line();
      std::vector<long long> nodes(info.num_nodes);
      for (long long& node : nodes)
        node = in.integer("a node tag of element " + std::to_string(tag));
      if (type == 3) {
        msh.quads.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
        msh.quad_tags.push_back(tag);
        msh.quad_lines.push_back(line);
        continue;
      }
      const auto phys = msh.physicals.find({dim, entity});
      if (phys == msh.physicals.end()) continue;
      for (int p : phys->second) {
        const auto name = msh.physical_names.find({dim, p});
        const std::string set = name != msh.physical_names.end()
                                    ? name->second
                                    : "physical_" + std::to_string(dim) + "_" + std::to_string(p);
        auto& tags = msh.set_tags[set];
        tags.insert(tags.end(), nodes.begin(), nodes.end());
      }
    }
  }
  in.expect("$EndElements");
}

MshContent read_sections(const std::string& path) {
  TokenStream in(path);
  MshContent msh;
  bool have_format = false, have_nodes = false, have_elements = false;
  while (!in.at_end()) {
    const std::string section = in.token("a section");
    if (!have_format && section != "$MeshFormat")
      in.fail("not a Gmsh MSH file: expected $MeshFormat", section);
    if (section == "$MeshFormat") {
      read_format(in);
      have_format = true;
    } else if (section == "$PhysicalNames") {
      read_physical_names(in, msh);
    } else if (section == "$Entities") {
      read_entities(in, msh);
    } else if (section == "$Nodes") {
      read_nodes(in, msh);
      have_nodes = true;
    } else if (section == "$Elements") {
      if (!have_nodes) in.fail("$Elements comes before $Nodes");
      read_elements(in, msh);
      have_elements = true;
    } else if (section.size() > 1 && section[0] == '$') {
      in.skip_to("$End" + section.substr(1));
    } else {
      in.fail("expected a section such as $Nodes", section);
    }
  }
  if (!have_format) in.fail("empty file: expected $MeshFormat");
  if (!have_elements) in.fail("the file has no $Elements section (truncated file?)");
  return msh;
}

Mesh to_mesh(const MshContent& msh, const std::string& path) {
  if (msh.quads.empty()) throw_input("the file has no 4-node quadrangles", {path, "", "", 0});
  std::map<long long, int> index;  // Gmsh node tag -> dense index, in tag order
  for (size_t q = 0; q < msh.quads.size(); ++q) {
    for (long long tag : msh.quads[q]) {
      if (msh.nodes.count(tag) == 0) {
        throw_input("element " + std::to_string(msh.quad_tags[q]) + " references node " +
                        std::to_string(tag) + ", which $Nodes does not define",
                    {path, "", "", msh.quad_lines[q]});
      }
      index[tag] = 0;
    }
  }
  Mesh mesh;
  for (auto& [tag, i] : index) {
    i = mesh.num_nodes();
    mesh.nodes.push_back(msh.nodes.at(tag));
  }
  for (const auto& q : msh.quads) {
    mesh.elements.push_back({index.at(q[0]), index.at(q[1]), index.at(q[2]), index.at(q[3])});
  }
  for (const auto& [name, tags] : msh.set_tags) {
    std::vector<int> set;
    for (long long tag : tags) {
      const auto it = index.find(tag);
      if (it == index.end()) {
        throw_input("node " + std::to_string(tag) + " of physical group '" + name +
                        "' belongs to no quadrangle",
                    {path, "", "", 0});
      }
      set.push_back(it->second);
    }
    set_node_set(mesh, name, set);
  }
  return mesh;
}

}  // namespace

Mesh read_gmsh_msh4(const std::string& path) {
  const MshContent msh = read_sections(path);
  Mesh mesh = to_mesh(msh, path);
  if (const auto pair = find_inconsistent_orientation(mesh)) {
    const int a = pair->first, b = pair->second;
    throw_input("elements " + std::to_string(msh.quad_tags[a]) + " (line " +
                    std::to_string(msh.quad_lines[a]) + ") and " +
                    std::to_string(msh.quad_tags[b]) +
                    " traverse their shared edge in the same direction: the orientation is "
                    "inconsistent (reorient the surface in Gmsh)",
                {path, "", "", msh.quad_lines[b]});
  }
  compute_directors_from_elements(mesh);
  // Element problems are reported with the element's Gmsh tag and line.
  for (int e = 0; e < mesh.num_elements(); ++e) {
    try {
      check_element(mesh, e);
    } catch (const Error& error) {
      throw_input(error.reason() + " [Gmsh element " + std::to_string(msh.quad_tags[e]) + "]",
                  {path, "", "", msh.quad_lines[e]});
    }
  }
  try {
    check_mesh(mesh);
  } catch (const Error& error) {
    throw error.within({path, "", "", 0});
  }
  return mesh;
}

}  // namespace si
