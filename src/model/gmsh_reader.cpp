#include "model/gmsh_reader.hpp"

#include <algorithm>
#include <numeric>

#include "core/error.hpp"
#include "model/gmsh_content.hpp"
#include "model/mesh_quality.hpp"
#include "model/mesh_topology.hpp"

namespace si {
namespace {

// $MeshFormat: the version decides the parser; a binary file then holds the integer 1 in the
// writer's byte order.
void read_format(MshScanner& in, GmshContent& out, std::string& version) {
  const std::string first(in.token("$MeshFormat"));
  if (first != "$MeshFormat") in.fail("not a Gmsh MSH file: expected $MeshFormat", first);
  version = std::string(in.token("the MSH version"));
  const long long file_type = in.integer("the file type");
  const long long data_size = in.integer("the data size");
  if (version != "4.1" && version != "2.2")
    in.fail("MSH version " + version +
                " is not supported: export as 4.1 (text or binary; Gmsh: -format msh41 or "
                "Mesh.MshFileVersion = 4.1) or 2.2 text",
            version);
  if (file_type != 0 && file_type != 1)
    in.fail("the file type must be 0 (text) or 1 (binary)", std::to_string(file_type));
  out.binary = file_type == 1;
  if (out.binary && version == "2.2")
    in.fail("binary MSH 2.2 files are not supported: export as 4.1 (text or binary) or 2.2 text");
  if (data_size != 8 && data_size != 4)
    in.fail("the data size must be 8 (or 4)", std::to_string(data_size));
  out.size_bytes = static_cast<int>(data_size);
  in.set_size_bytes(out.size_bytes);
  if (out.binary) {
    in.skip_line_break();
    if (in.binary<int>("the byte-order mark") != 1)
      in.fail("the binary file was written with the other byte order; export it as text");
  }
  in.expect("$EndMeshFormat");
}

[[noreturn]] void fail_at_quad(const GmshContent& c, const std::string& path, int quad,
                               const std::string& reason) {
  const int line = c.binary ? 0 : static_cast<int>(c.quad_positions[quad]);
  throw_input(c.describe_quad(quad) + " " + reason, {path, "", "", line});
}

// Dense node indices in the order of the Gmsh tags.
class NodeIndex {
 public:
  NodeIndex(const GmshContent& c, const std::string& path) : tags_(c.node_tags) {
    order_.resize(tags_.size());
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return tags_[a] < tags_[b]; });
    for (std::size_t k = 1; k < order_.size(); ++k)
      if (tags_[order_[k]] == tags_[order_[k - 1]])
        throw_input("node tag " + std::to_string(tags_[order_[k]]) + " is defined twice",
                    {path, "", "", 0});
  }

  // Position in c.node_tags of a tag, or -1.
  int find(long long tag) const {
    const auto it = std::lower_bound(order_.begin(), order_.end(), tag,
                                     [&](int k, long long t) { return tags_[k] < t; });
    return it != order_.end() && tags_[*it] == tag ? *it : -1;
  }
  const std::vector<int>& by_tag() const { return order_; }

 private:
  const std::vector<long long>& tags_;
  std::vector<int> order_;
};

// The mesh of the quadrangles; node_tag[n] is the Gmsh tag of mesh node n.
Mesh to_mesh(const GmshContent& c, const std::string& path, std::vector<long long>& node_tag) {
  if (c.quads.empty())
    throw_input(
        "the file has no 4-node quadrangles (a shell mesh is a surface mesh of quadrangles)",
        {path, "", "", 0});
  const NodeIndex index(c, path);
  std::vector<int> dense(c.node_tags.size(), -1);  // position in node_tags -> mesh node
  std::vector<std::array<int, 4>> quads(c.quads.size());
  for (std::size_t q = 0; q < c.quads.size(); ++q) {
    for (int a = 0; a < 4; ++a) {
      const int k = index.find(c.quads[q][a]);
      if (k < 0)
        fail_at_quad(
            c, path, static_cast<int>(q),
            "references node " + std::to_string(c.quads[q][a]) + ", which $Nodes does not define");
      quads[q][a] = k;
      dense[k] = 0;
    }
  }
  Mesh mesh;
  for (int k : index.by_tag()) {
    if (dense[k] < 0) continue;
    dense[k] = mesh.num_nodes();
    mesh.nodes.push_back(c.node_positions[k]);
    node_tag.push_back(c.node_tags[k]);
  }
  mesh.elements.reserve(quads.size());
  for (const auto& q : quads)
    mesh.elements.push_back({dense[q[0]], dense[q[1]], dense[q[2]], dense[q[3]]});
  for (const auto& [name, tags] : c.node_sets) {
    std::vector<int> set;
    for (long long tag : tags) {
      const int k = index.find(tag);
      if (k < 0 || dense[k] < 0)
        throw_input("node " + std::to_string(tag) + " of physical group '" + name + "' " +
                        (k < 0 ? "is not defined in $Nodes" : "belongs to no quadrangle"),
                    {path, "", name, 0});
      set.push_back(dense[k]);
    }
    set_node_set(mesh, name, set);
  }
  for (const auto& [name, quads_in_set] : c.element_sets) {
    std::vector<int> set = quads_in_set;
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    mesh.element_sets[name] = set;
  }
  return mesh;
}

// Degenerate and folded quadrangles, judged by themselves (before neighbours and directors):
// a repeated node, no area, or corners out of order (a "bow-tie": the corner Jacobians about
// the element's own normal change sign).
void check_element_shapes(const GmshContent& c, const std::string& path, const Mesh& mesh,
                          const std::vector<long long>& node_tag) {
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto& el = mesh.elements[e];
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (el[a] == el[b])
          fail_at_quad(c, path, e,
                       "repeats node " + std::to_string(node_tag[el[a]]) +
                           ": a degenerate quadrangle (a triangle in disguise)");
    const auto x = element_corners(mesh, e);
    const Vector3d n = element_normal(mesh, e);
    bool folded = n.isZero(0);
    for (int k = 0; k < 4 && !folded; ++k)
      folded = (x[(k + 1) % 4] - x[k]).cross(x[(k + 3) % 4] - x[k]).dot(n) <= 0;
    if (folded)
      fail_at_quad(c, path, e,
                   "is inverted or degenerate: its corners are not in order around it (a "
                   "self-crossing or collapsed quadrangle; corner Jacobian <= 0)");
  }
}

void check_topology(const GmshContent& c, const std::string& path, const GmshReadOptions& options,
                    const std::vector<long long>& node_tag, Mesh& mesh,
                    std::vector<std::string>& warnings) {
  const auto gmsh_node = [&](int n) { return std::to_string(node_tag[n]); };
  if (const auto edge = find_non_manifold_edge(mesh)) {
    std::string others;
    for (std::size_t k = 1; k < edge->elements.size(); ++k)
      others += (k > 1 ? ", " : "") + c.describe_quad(edge->elements[k]);
    fail_at_quad(c, path, edge->elements.front(),
                 "shares the edge between nodes " + gmsh_node(edge->a) + " and " +
                     gmsh_node(edge->b) + " with " + others +
                     ": a non-manifold edge (more than two elements on one edge), which a shell "
                     "surface cannot have");
  }
  const OrientationFix fix = consistent_orientation(mesh);
  if (fix.conflict)
    fail_at_quad(c, path, fix.conflict->second,
                 "cannot be oriented consistently with " + c.describe_quad(fix.conflict->first) +
                     ": the surface is not orientable (a Moebius strip), so no director field "
                     "exists");
  if (fix.flip.empty()) return;
  if (!options.reorient) {
    const int first = fix.flip.front();
    fail_at_quad(c, path, first,
                 "is oriented opposite to its neighbours (its nodes run clockwise where theirs "
                 "run counter-clockwise; " +
                     std::to_string(fix.flip.size()) +
                     " element(s) in all): reverse it in Gmsh (Reverse Surface / "
                     "ReorientMesh) or set `mesh.reorient: true`");
  }
  reverse_elements(mesh, fix.flip);
  std::string list;
  for (std::size_t k = 0; k < std::min<std::size_t>(fix.flip.size(), 5); ++k)
    list += (k > 0 ? ", " : "") + std::to_string(c.quad_tags[fix.flip[k]]);
  warnings.push_back(
      path + ": reversed " + std::to_string(fix.flip.size()) +
      " element(s) to agree with their neighbours (mesh.reorient): Gmsh element(s) " + list +
      (fix.flip.size() > 5 ? ", ..." : ""));
}

void check_elements(const GmshContent& c, const std::string& path, const Mesh& mesh) {
  for (int e = 0; e < mesh.num_elements(); ++e) {
    try {
      check_element(mesh, e);
    } catch (const Error& error) {
      // check_element names the element by its index; the user knows the Gmsh tag and line.
      const std::string reason = error.reason();
      const std::size_t cut = reason.find(')');
      fail_at_quad(c, path, e, cut == std::string::npos ? reason : reason.substr(cut + 2));
    }
  }
}

}  // namespace

ImportedMesh read_gmsh_mesh(const std::string& path, const GmshReadOptions& options) {
  GmshContent content;
  {
    MshScanner in(path);
    std::string version;
    read_format(in, content, version);
    if (version == "4.1")
      read_msh41_sections(in, content);
    else
      read_msh22_sections(in, content);
  }
  ImportedMesh out;
  std::vector<long long> node_tag;
  out.mesh = to_mesh(content, path, node_tag);
  check_element_shapes(content, path, out.mesh, node_tag);
  check_topology(content, path, options, node_tag, out.mesh, out.warnings);
  compute_directors_from_elements(out.mesh);
  check_elements(content, path, out.mesh);
  try {
    check_mesh(out.mesh);
  } catch (const Error& error) {
    throw error.within({path, "", "", 0});
  }
  if (options.flip) flip_orientation(out.mesh);
  return out;
}

}  // namespace si
