#include "model/shell_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "model/cylindrical_panel_mesh.hpp"
#include "model/plate_meshes.hpp"
#include "model/spherical_cap_mesh.hpp"
#include "section/clt_section.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Smallest even number of equal elements (>= 2) of side at most h over a length.
int even_count(double length, double h) {
  return 2 * std::max(1, static_cast<int>(std::ceil(length / (2.0 * h) - 1e-9)));
}

std::vector<int> set_union(const Mesh& mesh, const std::vector<std::string>& names) {
  std::vector<int> out;
  for (const auto& n : names) {
    const auto& s = mesh.node_sets.at(n);
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

Mesh rectangular_mesh(const ShellSpec& shell, const MeshSpec& spec) {
  const int nx = even_count(shell.length_x, spec.size_apex);
  const int ny = even_count(shell.length_y, spec.size_apex);
  if (spec.symmetry == Symmetry::kQuarter) {
    // [0, lx/2] x [0, ly/2]: the centre is node 0, x = 0 and y = 0 are the symmetry planes.
    Mesh m = rectangular_plate_mesh(shell.length_x / 2, shell.length_y / 2, nx / 2, ny / 2);
    set_node_set(m, "apex", {0});
    set_node_set(m, "symmetry_x", m.node_sets.at("edge_x0"));
    set_node_set(m, "symmetry_y", m.node_sets.at("edge_y0"));
    set_node_set(m, "edge", set_union(m, {"edge_x1", "edge_y1"}));
    return m;
  }
  Mesh m = rectangular_plate_mesh(shell.length_x, shell.length_y, nx, ny);
  for (auto& x : m.nodes) x -= Vector3d(shell.length_x / 2, shell.length_y / 2, 0);
  set_node_set(m, "apex", m.node_sets.at("center"));
  return m;
}

Mesh panel_mesh(const ShellSpec& shell, const MeshSpec& spec) {
  const int n_circ = even_count(shell.radius * shell.angle_deg * kPi / 180.0, spec.size_apex);
  const int n_axial = even_count(shell.length, spec.size_apex);
  const bool quarter = spec.symmetry == Symmetry::kQuarter;
  Mesh m = cylindrical_panel_mesh(shell.radius, shell.length, shell.angle_deg / 2,
                                  quarter ? n_axial / 2 : n_axial, quarter ? n_circ / 2 : n_circ,
                                  quarter ? PanelPart::kQuarter : PanelPart::kFull);
  set_node_set(m, "apex", m.node_sets.at("center"));
  set_node_set(m, "edge", set_union(m, {"curved_ends", "straight_edges"}));
  if (quarter) {
    set_node_set(m, "symmetry_x", m.node_sets.at("crown"));
    set_node_set(m, "symmetry_y", m.node_sets.at("axial_midplane"));
  }
  return m;
}

// Element count of the requested mesh, from above (the graded disk meshes have size_apex
// within refine_radius and size_edge outside it), so that an absurd size is refused before the
// generator tries to allocate it.
double estimated_element_count(const ShellSpec& shell, const MeshSpec& mesh) {
  switch (shell.type) {
    case ShellType::kSphericalCap:
    case ShellType::kFlatCircularPlate: {
      const double r = shell.type == ShellType::kSphericalCap ? shell.base_radius : shell.radius;
      const double inner = std::min(mesh.refine_radius, r);
      // Cap surface area exceeds its plan area by at most a factor 2 (hemisphere).
      return 2.0 * kPi *
             (inner * inner / (mesh.size_apex * mesh.size_apex) +
              r * r / (mesh.size_edge * mesh.size_edge));
    }
    case ShellType::kRectangularPlate:
      return shell.length_x * shell.length_y / (mesh.size_apex * mesh.size_apex);
    case ShellType::kCylindricalPanel:
      return shell.radius * shell.angle_deg * kPi / 180.0 * shell.length /
             (mesh.size_apex * mesh.size_apex);
  }
  return 0;
}

constexpr double kMaxElements = 4e6;  // ~1e8 dofs: beyond any 24 GB machine's direct solver

void check_mesh_size(const ShellModelSpec& c) {
  const double n = estimated_element_count(c.shell, c.mesh);
  if (n > kMaxElements) {
    std::ostringstream os;
    os << "this element size asks for about " << std::llround(n) << " elements, more than the "
       << kMaxElements << " a direct solver can handle on one machine; use a larger size";
    throw_input(os.str(),
                Where{c.file, "mesh.size_apex", std::to_string(c.mesh.size_apex) + " mm", 0});
  }
}

// The mesh generators name their own parameters (size_apex, base_radius, ...); report them with
// the case file and the dotted key the user wrote.
Mesh shell_mesh_in_case(const ShellModelSpec& c) {
  try {
    return shell_mesh(c.shell, c.mesh);
  } catch (const Error& e) {
    const std::string& key = e.where().key;
    const bool mesh_key = key.rfind("size_", 0) == 0 || key == "refine_radius";
    const std::string path = key.empty() ? "" : (mesh_key ? "mesh." : "shell.") + key;
    throw Error(e.kind(), e.reason(), Where{c.file, path, e.where().value, 0});
  }
}

void check_quarter_symmetry(const ShellModelSpec& c, const Matrix6d& A_R) {
  if (c.mesh.symmetry != Symmetry::kQuarter) return;
  if (is_specially_orthotropic(A_R, 1e-10)) return;
  throw_input(
      "a quarter model needs a section that is specially orthotropic in the model axes (A16 = "
      "A26 = D16 = D26 = 0 and B = 0 about the reference surface); this laminate's is not (an "
      "angle ply such as [45/-45]2S has bending-twisting coupling, so its response has no mirror "
      "symmetry about x = 0 and y = 0: paper-notes.md item 2). Use symmetry: full",
      Where{c.file, "mesh.symmetry", "quarter", 0});
}

std::vector<Support> edge_supports(const ShellModelSpec& c) {
  std::vector<Support> supports;
  const bool quarter = c.mesh.symmetry == Symmetry::kQuarter;
  switch (c.shell.edge) {
    case EdgeCondition::kClamped:
      supports.push_back({SupportKind::kClamped, "edge", -1, {}});
      break;
    case EdgeCondition::kHinged:
      supports.push_back({SupportKind::kHinged, "edge", -1, {}});
      break;
    case EdgeCondition::kSimplySupported: {
      const bool flat = c.shell.type == ShellType::kFlatCircularPlate ||
                        c.shell.type == ShellType::kRectangularPlate;
      if (!flat)
        throw_input(
            "simply_supported needs a flat plate (the deflection along the director is a "
            "dof only where the director is a global axis); use hinged",
            Where{c.file, "shell.edge", "simply_supported", 0});
      supports.push_back({SupportKind::kSimplySupported, "edge", -1, {}});
      if (!quarter) {
        // The in-plane rigid-body motions: both translations at the centre, and the rotation
        // about z by u_y at the rim node of largest x.
        supports.push_back({SupportKind::kFixedDofs, "apex", -1, {0, 1}});
        supports.push_back({SupportKind::kFixedDofs, "rim_x", -1, {1}});
      }
      break;
    }
    case EdgeCondition::kFree:
      throw_input(
          "a free edge leaves the shell without supports (free rigid-body motion); use clamped, "
          "hinged or simply_supported",
          Where{c.file, "shell.edge", "free", 0});
  }
  if (quarter) {
    supports.push_back({SupportKind::kSymmetryPlane, "symmetry_x", 0, {}});
    supports.push_back({SupportKind::kSymmetryPlane, "symmetry_y", 1, {}});
  }
  return supports;
}

}  // namespace

Mesh shell_mesh(const ShellSpec& shell, const MeshSpec& spec) {
  switch (shell.type) {
    case ShellType::kSphericalCap: {
      SphericalCapMeshSpec s;
      s.base_radius = shell.base_radius;
      s.sphere_radius = shell.radius;
      s.size_apex = spec.size_apex;
      s.size_edge = spec.size_edge;
      s.refine_radius = spec.refine_radius;
      s.symmetry = spec.symmetry;
      return spherical_cap_mesh(s);
    }
    case ShellType::kFlatCircularPlate: {
      Mesh m = circular_plate_mesh(shell.radius, spec.size_apex, spec.size_edge, spec.refine_radius,
                                   spec.symmetry);
      set_node_set(m, "apex", m.node_sets.at("center"));
      return m;
    }
    case ShellType::kRectangularPlate:
      return rectangular_mesh(shell, spec);
    case ShellType::kCylindricalPanel:
      return panel_mesh(shell, spec);
  }
  throw_input("unknown shell type");
}

Loads shell_loads(const LoadSpec& load, double symmetry_factor) {
  Loads loads;
  if (load.type == LoadType::kApexForce)
    loads.points.push_back({"apex", Vector3d(0, 0, -load.force / symmetry_factor), false});
  else  // loads.hpp: a positive pressure pushes towards the director side; ours acts against it
    loads.pressures.push_back({-load.pressure, load.follower, {}});
  return loads;
}

ShellModel build_shell_model(const ShellModelSpec& c) {
  ShellModel model;
  const VamSection vam = analyze_vam(c.laminate);
  check_quarter_symmetry(c, vam.A_R);
  model.law.A_R = vam.A_R;
  model.law.G = vam.G;
  check_mesh_size(c);
  model.mesh = shell_mesh_in_case(c);
  if (c.shell.edge == EdgeCondition::kSimplySupported && c.mesh.symmetry == Symmetry::kFull) {
    // Rim node of largest x (on the positive x axis for the plates).
    const auto& edge = model.mesh.node_sets.at("edge");
    const int rim = *std::max_element(edge.begin(), edge.end(), [&](int a, int b) {
      return model.mesh.nodes[a].x() < model.mesh.nodes[b].x();
    });
    set_node_set(model.mesh, "rim_x", {rim});
  }
  model.element = make_shell_element(c.mesh.element);
  if (c.mesh.element == ElementType::kBernstein4)
    model.warnings.push_back(
        "mesh.element = bernstein4: the source paper's element has no partition of unity and "
        "fails the patch test (paper-notes.md item 1); use it to reproduce the paper, not for "
        "results");
  model.kinematics = c.kinematics;
  model.symmetry_factor = c.mesh.symmetry == Symmetry::kQuarter ? 4.0 : 1.0;
  model.supports = edge_supports(c);
  if (c.load) model.loads = shell_loads(*c.load, model.symmetry_factor);
  return model;
}

}  // namespace si
