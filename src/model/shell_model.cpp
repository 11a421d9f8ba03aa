#include "model/shell_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/constants.hpp"
#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "model/cylindrical_panel_mesh.hpp"
#include "model/fixture.hpp"
#include "model/gmsh_reader.hpp"
#include "model/graded_stations.hpp"
#include "model/imported_mesh_sets.hpp"
#include "model/mesh_topology.hpp"
#include "model/plate_meshes.hpp"
#include "model/spherical_cap_mesh.hpp"
#include "section/clt_section.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

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

LineGrading line_grading(const MeshSpec& spec) {
  return {spec.size_apex, spec.size_edge, refine_radius_or_default(spec)};
}

// Stations from the centre outwards, mirrored for the full model.
std::vector<double> graded(double half_length, const MeshSpec& spec) {
  const std::vector<double> half = centred_graded_stations(half_length, line_grading(spec));
  return spec.symmetry == Symmetry::kQuarter ? half : mirrored(half);
}

// The stations of a plate side with a mesh line at +-line (graded or uniform), mirrored for the
// full model.
std::vector<double> stations_with_line(double half_length, double line, const MeshSpec& spec) {
  std::vector<double> half;
  if (spec.graded) {
    half = centred_graded_stations(half_length, line_grading(spec));
  } else {
    const int n = even_count(2 * half_length, spec.size_apex) / 2;
    for (int k = 0; k <= n; ++k) half.push_back(half_length * k / n);
  }
  half = with_station(half, line);
  return spec.symmetry == Symmetry::kQuarter ? half : mirrored(half);
}

// The subset of `set` whose coordinate `axis` has the sign of `sign`.
std::vector<int> side_of(const Mesh& m, const std::string& set, int axis, double sign) {
  std::vector<int> out;
  for (int n : m.node_sets.at(set))
    if (sign * m.nodes[n][axis] > 0) out.push_back(n);
  return out;
}

// The nodes on the rectangle |x| = line_x, |y| <= line_y or |y| = line_y, |x| <= line_x.
std::vector<int> rectangle_nodes(const Mesh& m, const MeshSpec& spec) {
  const double tol = 1e-9 * (spec.line_x + spec.line_y);
  return nodes_where(m, [&](const Vector3d& p) {
    const double x = std::abs(p.x()), y = std::abs(p.y());
    return (std::abs(x - spec.line_x) < tol && y < spec.line_y + tol) ||
           (std::abs(y - spec.line_y) < tol && x < spec.line_x + tol);
  });
}

Mesh rectangular_mesh(const ShellSpec& shell, const MeshSpec& spec) {
  const bool quarter = spec.symmetry == Symmetry::kQuarter;
  Mesh m;
  if (spec.line_x > 0 || spec.line_y > 0) {
    m = rectangular_plate_mesh(stations_with_line(shell.length_x / 2, spec.line_x, spec),
                               stations_with_line(shell.length_y / 2, spec.line_y, spec));
  } else if (spec.graded) {
    m = rectangular_plate_mesh(graded(shell.length_x / 2, spec), graded(shell.length_y / 2, spec));
  } else {
    const int nx = even_count(shell.length_x, spec.size_apex);
    const int ny = even_count(shell.length_y, spec.size_apex);
    // Quarter: [0, lx/2] x [0, ly/2], the centre is node 0; full: centred on the origin.
    m = quarter ? rectangular_plate_mesh(shell.length_x / 2, shell.length_y / 2, nx / 2, ny / 2)
                : rectangular_plate_mesh(shell.length_x, shell.length_y, nx, ny);
    if (!quarter)
      for (auto& x : m.nodes) x -= Vector3d(shell.length_x / 2, shell.length_y / 2, 0);
  }
  set_node_set(m, "x+", m.node_sets.at("edge_x1"));
  set_node_set(m, "y+", m.node_sets.at("edge_y1"));
  if (spec.line_x > 0 && spec.line_y > 0) set_node_set(m, "window_edge", rectangle_nodes(m, spec));
  if (quarter) {
    // x = 0 and y = 0 are the symmetry planes.
    set_node_set(m, "apex", {0});
    set_node_set(m, "symmetry_x", m.node_sets.at("edge_x0"));
    set_node_set(m, "symmetry_y", m.node_sets.at("edge_y0"));
    set_node_set(m, "edge", set_union(m, {"edge_x1", "edge_y1"}));
    return m;
  }
  set_node_set(m, "x-", m.node_sets.at("edge_x0"));
  set_node_set(m, "y-", m.node_sets.at("edge_y0"));
  set_node_set(m, "apex", m.node_sets.at("center"));
  return m;
}

Mesh panel_mesh(const ShellSpec& shell, const MeshSpec& spec) {
  const int n_circ = even_count(shell.radius * shell.angle_deg * kPi / 180.0, spec.size_apex);
  const int n_axial = even_count(shell.length, spec.size_apex);
  const bool quarter = spec.symmetry == Symmetry::kQuarter;
  const PanelPart part = quarter ? PanelPart::kQuarter : PanelPart::kFull;
  Mesh m;
  if (spec.graded) {
    // Graded in arc length: the element size holds on the surface.
    std::vector<double> thetas = graded(shell.radius * shell.angle_deg * kPi / 360.0, spec);
    for (double& t : thetas) t /= shell.radius;
    m = cylindrical_panel_mesh(shell.radius, thetas, graded(shell.length / 2, spec), part);
  } else {
    m = cylindrical_panel_mesh(shell.radius, shell.length, shell.angle_deg / 2,
                               quarter ? n_axial / 2 : n_axial, quarter ? n_circ / 2 : n_circ,
                               part);
  }
  set_node_set(m, "apex", m.node_sets.at("center"));
  set_node_set(m, "x+", side_of(m, "straight_edges", 0, 1));
  set_node_set(m, "y+", side_of(m, "curved_ends", 1, 1));
  if (!quarter) {
    set_node_set(m, "x-", side_of(m, "straight_edges", 0, -1));
    set_node_set(m, "y-", side_of(m, "curved_ends", 1, -1));
  }
  set_node_set(m, "edge", set_union(m, {"curved_ends", "straight_edges"}));
  if (quarter) {
    set_node_set(m, "symmetry_x", m.node_sets.at("crown"));
    set_node_set(m, "symmetry_y", m.node_sets.at("axial_midplane"));
  }
  return m;
}

std::string text_of_edge(EdgeCondition edge) {
  switch (edge) {
    case EdgeCondition::kClamped:
      return "clamped";
    case EdgeCondition::kHinged:
      return "hinged";
    case EdgeCondition::kSimplySupported:
      return "simply_supported";
    case EdgeCondition::kFree:
      return "free";
  }
  return "";
}

// Elements along a line through the centre: uniform at size_apex, or graded (the integral of
// 1/size with the size growing linearly from size_apex to size_edge beyond refine_radius).
double line_count(double length, const MeshSpec& mesh) {
  const double half = length / 2, ha = mesh.size_apex, he = mesh.size_edge;
  const double refine = refine_radius_or_default(mesh);
  if (!mesh.graded || refine >= half || he <= ha) return length / ha;
  return 2 * (refine / ha + (half - refine) * std::log(he / ha) / (he - ha));
}

// Element count of the requested mesh, from above (the graded disk meshes have size_apex
// within refine_radius and size_edge outside it), so that an absurd size is refused before the
// generator tries to allocate it.
double estimated_element_count(const ShellSpec& shell, const MeshSpec& mesh) {
  switch (shell.type) {
    case ShellType::kSphericalCap:
    case ShellType::kFlatCircularPlate: {
      const double r = shell.type == ShellType::kSphericalCap ? shell.base_radius : shell.radius;
      const double inner = std::min(refine_radius_or_default(mesh), r);
      // Cap surface area exceeds its plan area by at most a factor 2 (hemisphere).
      return 2.0 * kPi *
             (inner * inner / (mesh.size_apex * mesh.size_apex) +
              r * r / (mesh.size_edge * mesh.size_edge));
    }
    case ShellType::kRectangularPlate:
      return line_count(shell.length_x, mesh) * line_count(shell.length_y, mesh);
    case ShellType::kCylindricalPanel:
      return line_count(shell.radius * shell.angle_deg * kPi / 180.0, mesh) *
             line_count(shell.length, mesh);
  }
  return 0;
}

constexpr double kMaxElements = 4e6;  // ~1e8 dofs: beyond any 24 GB machine's direct solver

void check_mesh_size(const ShellModelSpec& c) {
  if (!c.mesh.file.empty()) return;  // the reader bounds a file's counts by its size
  const double n = estimated_element_count(c.shell, c.mesh);
  if (n > kMaxElements) {
    std::ostringstream os;
    os << "this element size asks for about " << std::llround(n) << " elements, more than the "
       << kMaxElements << " a direct solver can handle on one machine; use a larger size";
    throw_input(os.str(), Where{c.file, "mesh.size_apex",
                                format_quantity(c.mesh.size_apex, Dimension::kLength), 0});
  }
}

// The mesh generators name their own parameters (size_apex, base_radius, ...); report them with
// the case file and the dotted key the user wrote.
Mesh shell_mesh_in_case(const ShellModelSpec& c, std::vector<std::string>& warnings) {
  if (!c.mesh.file.empty()) {
    GmshReadOptions options;
    options.reorient = c.mesh.reorient;
    options.flip = c.mesh.flip;
    ImportedMesh imported = read_gmsh_mesh(c.mesh.file, options);
    warnings.insert(warnings.end(), imported.warnings.begin(), imported.warnings.end());
    try {
      add_imported_mesh_sets(imported.mesh, c.mesh.symmetry);
    } catch (const Error& e) {
      throw Error(e.kind(), e.reason() + " (in " + c.mesh.file + ")",
                  Where{c.file, "mesh.file", c.mesh.file, 0});
    }
    return std::move(imported.mesh);
  }
  MeshSpec spec = c.mesh;
  if (c.fixture.type == FixtureType::kAstmD7136) {  // mesh lines on the cut-out's edges
    spec.line_x = 0.5 * c.fixture.window_x;
    spec.line_y = 0.5 * c.fixture.window_y;
  }
  try {
    return shell_mesh(c.shell, spec);
  } catch (const Error& e) {
    const std::string& key = e.where().key;
    const bool mesh_key = key.rfind("size_", 0) == 0 || key == "refine_radius";
    const std::string path = key.empty() ? "" : (mesh_key ? "mesh." : "shell.") + key;
    // The generators print their numbers bare ("80.900000"): give them their unit. The CLI puts
    // the value as written back when the key is in the case file (io/case_key_location.hpp).
    std::string value = e.where().value;
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (!value.empty() && end == value.c_str() + value.size())
      value = format_quantity(
          number, key.find("angle") != std::string::npos ? Dimension::kAngle : Dimension::kLength);
    throw Error(e.kind(), e.reason(), Where{c.file, path, value, 0});
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

// A `supports`/`loads` entry names a set the mesh does not have: say which sets it has and the
// closest one.
[[noreturn]] void unknown_set(const Mesh& mesh, const std::string& name, const Where& where) {
  std::vector<std::string> names;
  for (const auto& [set, nodes] : mesh.node_sets) names.push_back(set);
  for (const auto& [set, elements] : mesh.element_sets)
    if (mesh.node_sets.count(set) == 0) names.push_back(set);
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw_input(
      "the mesh has no set '" + name + "'" + did_you_mean(name, names) + "; its sets are: " + list,
      where);
}

void check_set_names(const ShellModelSpec& c, const Mesh& mesh) {
  for (const NamedSupportSpec& s : c.shell.supports)
    if (mesh.node_sets.count(s.on) == 0) unknown_set(mesh, s.on, s.where);
  if (!c.load) return;
  for (const NamedLoadSpec& l : c.load->named)
    if (!l.on.empty() && mesh.node_sets.count(l.on) == 0 && mesh.element_sets.count(l.on) == 0)
      unknown_set(mesh, l.on, l.where);
}

SupportType support_type(EdgeCondition edge) {
  switch (edge) {
    case EdgeCondition::kClamped:
      return SupportType::kClamped;
    case EdgeCondition::kHinged:
      return SupportType::kHinged;
    case EdgeCondition::kSimplySupported:
      return SupportType::kSimplySupported;
    case EdgeCondition::kFree:
      return SupportType::kFree;
  }
  return SupportType::kClamped;
}

// Supports of a case with `supports:` entries or a mesh file (named_supports.hpp): the entries,
// `shell.edge` on the rest of the boundary, the symmetry planes, and for a flat plate the
// in-plane rigid-body motions that simply supported or free edges leave.
// With a fixture (apply_fixture: its clamps in `fixture_supports`) the plate's edges are free and
// the frame holds it: nothing else need.
SupportPlan named_supports(const ShellModelSpec& c, Mesh& mesh,
                           const std::vector<Support>& fixture_supports) {
  const bool quarter = c.mesh.symmetry == Symmetry::kQuarter;
  const bool on_frame = c.fixture.type != FixtureType::kNone;
  const std::vector<std::string> planes =
      quarter ? std::vector<std::string>{"symmetry_x", "symmetry_y"} : std::vector<std::string>{};
  SupportPlan plan = plan_supports(
      mesh, c.shell.supports, support_type(on_frame ? EdgeCondition::kFree : c.shell.edge), planes);
  plan.supports.insert(plan.supports.end(), fixture_supports.begin(), fixture_supports.end());
  if (quarter) {
    plan.supports.push_back({SupportKind::kSymmetryPlane, "symmetry_x", 0, {}});
    plan.supports.push_back({SupportKind::kSymmetryPlane, "symmetry_y", 1, {}});
  }
  try {
    prescribed_dofs(mesh, plan.supports, plan.displacements);
  } catch (const Error& e) {
    throw Error(e.kind(), e.reason(), Where{c.file, "shell.edge", text_of_edge(c.shell.edge), 0});
  }
  if (plan.supports.empty() && plan.displacements.empty() && !on_frame)
    throw_input(
        "nothing holds the shell (every edge free, no support entry): it would move as a "
        "rigid body",
        Where{c.file, "supports", "", 0});
  const std::vector<int> rim = boundary_nodes(mesh);
  const int far = *std::max_element(
      rim.begin(), rim.end(), [&](int a, int b) { return mesh.nodes[a].x() < mesh.nodes[b].x(); });
  set_node_set(mesh, "rim_x", {far});
  hold_inplane_rigid_body(mesh, "apex", "rim_x", plan);
  return plan;
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
      s.refine_radius = refine_radius_or_default(spec);
      s.symmetry = spec.symmetry;
      Mesh m = spherical_cap_mesh(s);
      set_node_set(m, "rim", m.node_sets.at("edge"));
      return m;
    }
    case ShellType::kFlatCircularPlate: {
      Mesh m = circular_plate_mesh(shell.radius, spec.size_apex, spec.size_edge,
                                   refine_radius_or_default(spec), spec.symmetry);
      set_node_set(m, "apex", m.node_sets.at("center"));
      set_node_set(m, "rim", m.node_sets.at("edge"));
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
  if (load.type == LoadType::kNone) return loads;
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
  model.mesh = shell_mesh_in_case(c, model.warnings);
  std::vector<Support> fixture_supports;
  if (c.fixture.type != FixtureType::kNone)
    model.frame_nodes = apply_fixture(c.fixture, c.file, model.mesh, fixture_supports);
  check_set_names(c, model.mesh);
  const bool named =
      !c.mesh.file.empty() || !c.shell.supports.empty() || !model.frame_nodes.empty();
  if (!named && c.shell.edge == EdgeCondition::kSimplySupported &&
      c.mesh.symmetry == Symmetry::kFull) {
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
  if (named) {
    SupportPlan plan = named_supports(c, model.mesh, fixture_supports);
    model.supports = std::move(plan.supports);
    model.displacements = std::move(plan.displacements);
  } else {
    model.supports = edge_supports(c);
  }
  if (c.load) {
    model.loads = shell_loads(*c.load, model.symmetry_factor);
    const std::vector<std::string> planes =
        c.mesh.symmetry == Symmetry::kQuarter ? std::vector<std::string>{"symmetry_x", "symmetry_y"}
                                              : std::vector<std::string>{};
    add_named_loads(model.mesh, c.load->named, planes, model.loads);
  }
  return model;
}

}  // namespace si
