#include "io/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "core/units.hpp"
#include "io/damage_reader.hpp"
#include "io/fixture_reader.hpp"
#include "io/fraction_reader.hpp"
#include "io/laminate_reader.hpp"
#include "io/material_reader.hpp"
#include "io/named_sets_reader.hpp"
#include "io/path_reader.hpp"
#include "io/plausible_range.hpp"
#include "io/spellings.hpp"
#include "io/yaml_reader.hpp"

namespace si {
namespace {

const Choices<EdgeCondition> kEdges{{"clamped", EdgeCondition::kClamped},
                                    {"hinged", EdgeCondition::kHinged},
                                    {"simply_supported", EdgeCondition::kSimplySupported},
                                    {"free", EdgeCondition::kFree}};
const Choices<ShellType> kShellTypes{{"spherical_cap", ShellType::kSphericalCap},
                                     {"flat_circular_plate", ShellType::kFlatCircularPlate},
                                     {"rectangular_plate", ShellType::kRectangularPlate},
                                     {"cylindrical_panel", ShellType::kCylindricalPanel}};
const Choices<ElementType> kElements{{"mitc4", ElementType::kMitc4},
                                     {"mitc4-plain", ElementType::kMitc4Plain},
                                     {"bernstein4", ElementType::kBernstein4}};
const Choices<Symmetry> kSymmetries{{"full", Symmetry::kFull}, {"quarter", Symmetry::kQuarter}};
const Choices<bool> kGradings{{"uniform", false}, {"graded", true}};
const Choices<ErrorEstimate> kErrorEstimates{{"recovery", ErrorEstimate::kRecovery},
                                             {"companion", ErrorEstimate::kCompanion}};
const Choices<IndenterShape> kShapes{{"sphere", IndenterShape::kSphere},
                                     {"superquadric", IndenterShape::kSuperquadric},
                                     {"flat_punch", IndenterShape::kFlatPunch},
                                     {"cylinder", IndenterShape::kCylinder}};
const Choices<ContactSurface> kSurfaces{{"outer", ContactSurface::kOuter},
                                        {"mid", ContactSurface::kMid}};
const Choices<ContactSolver> kSolvers{{"kinsol", ContactSolver::kKinsol},
                                      {"active_set", ContactSolver::kActiveSet}};
const Choices<ContactTraction> kTractions{{"nodal", ContactTraction::kNodal},
                                          {"interpolated", ContactTraction::kInterpolated}};
const Choices<LoadType> kLoadTypes{{"apex_force", LoadType::kApexForce},
                                   {"pressure", LoadType::kPressure}};

// A section given as a map, or std::nullopt when the section is absent (defaults apply).
std::optional<MapReader> section(const MapReader& top, const std::string& key) {
  if (!top.has(key)) return std::nullopt;
  return MapReader(top.at(key), top.where(key));
}

// A section's geometry keys are required once the section is written: a partly written shell
// silently completed with the paper's numbers would be a surprise.
// With `mesh.file` the geometry comes from the file: `shell` may only give the default edge.
ShellSpec read_shell(const MapReader& top, bool imported) {
  ShellSpec shell;
  shell.supports = read_supports(top);
  const auto map = section(top, "shell");
  if (!map) return shell;
  if (imported) {
    map->allow_only({"edge"});
    shell.edge = map->choice_or("edge", kEdges, shell.edge);
    return shell;
  }
  shell.type = map->choice("type", kShellTypes);
  switch (shell.type) {
    case ShellType::kSphericalCap:
      map->allow_only({"type", "base_radius", "radius", "edge"});
      shell.base_radius = map->positive("base_radius", Dimension::kLength);
      shell.radius = map->positive("radius", Dimension::kLength);
      if (shell.base_radius >= shell.radius)
        throw_input("a spherical cap's base radius must be smaller than the sphere radius (" +
                        map->scalar("radius") + "): a hemisphere or more is not a cap",
                    map->where("base_radius"));
      break;
    case ShellType::kFlatCircularPlate:
      map->allow_only({"type", "radius", "edge"});
      shell.radius = map->positive("radius", Dimension::kLength);
      break;
    case ShellType::kRectangularPlate:
      map->allow_only({"type", "length_x", "length_y", "edge"});
      shell.length_x = map->positive("length_x", Dimension::kLength);
      shell.length_y = map->positive("length_y", Dimension::kLength);
      break;
    case ShellType::kCylindricalPanel:
      map->allow_only({"type", "radius", "length", "angle", "edge"});
      shell.radius = map->positive("radius", Dimension::kLength);
      shell.length = map->positive("length", Dimension::kLength);
      shell.angle_deg = map->positive("angle", Dimension::kAngle);
      if (shell.angle_deg > 360.0) throw_input("must not exceed 360 deg", map->where("angle"));
      break;
  }
  shell.edge = map->choice_or("edge", kEdges, shell.edge);
  return shell;
}

bool has_mesh_file(const MapReader& top) {
  return top.has("mesh") && top.at("mesh").IsMap() && top.at("mesh")["file"];
}

// mesh.file, resolved against the directory of the case file, must exist now (nothing is run or
// written for a case whose mesh cannot be read).
void read_mesh_file(const MapReader& map, MeshSpec& mesh) {
  map.allow_only(
      {"element", "file", "reorient", "flip", "symmetry", "tolerance", "error_estimate"});
  const std::filesystem::path file = map.scalar("file");
  const std::filesystem::path base = std::filesystem::path(map.where().file).parent_path();
  mesh.file = (file.is_absolute() ? file : base / file).string();
  if (!std::filesystem::is_regular_file(mesh.file))
    throw_input("cannot open the mesh file " + mesh.file +
                    " (a relative path is taken from the case file's directory)",
                map.where("file"));
  mesh.reorient = map.choice_or("reorient", boolean_spellings(), mesh.reorient);
  mesh.flip = map.choice_or("flip", boolean_spellings(), mesh.flip);
}

MeshSpec read_mesh(const MapReader& top, ShellType shell, bool graded) {
  MeshSpec mesh;
  mesh.graded = graded;  // a fixture's plate: graded unless `grading` says otherwise
  const auto map = section(top, "mesh");
  if (!map) return mesh;
  if (map->has("file")) {
    read_mesh_file(*map, mesh);
  } else {
    map->allow_only({"element", "size_apex", "size_edge", "refine_radius", "symmetry", "grading",
                     "tolerance", "error_estimate"});
    mesh.graded = map->choice_or("grading", kGradings, mesh.graded);
    const bool grid =
        shell == ShellType::kRectangularPlate || shell == ShellType::kCylindricalPanel;
    if (map->has("grading") && !grid && !mesh.graded)
      throw_input(
          "the O-grid of a cap or circular plate is always graded; for a uniform mesh set "
          "size_edge equal to size_apex",
          map->where("grading"));
  }
  mesh.element = map->choice_or("element", kElements, mesh.element);
  mesh.size_apex = map->positive_or("size_apex", Dimension::kLength, mesh.size_apex);
  mesh.size_edge = map->positive_or("size_edge", Dimension::kLength, mesh.size_edge);
  if (map->has("refine_radius"))
    mesh.refine_radius =
        map->positive_or("refine_radius", Dimension::kLength, kDefaultRefineRadius);
  mesh.symmetry = map->choice_or("symmetry", kSymmetries, mesh.symmetry);
  mesh.tolerance = fraction_or(*map, "tolerance", 0.0);
  mesh.error_estimate = map->choice_or("error_estimate", kErrorEstimates, mesh.error_estimate);
  if (!mesh.file.empty() && mesh.error_estimate == ErrorEstimate::kCompanion)
    throw_input(
        "an imported mesh (mesh.file) has no element sizes to double for a companion run: "
        "`companion` needs a built-in mesh (the Zienkiewicz-Zhu estimate, `recovery`, is always "
        "on)",
        map->where("error_estimate"));
  return mesh;
}

double read_exponent(const MapReader& map, const std::string& key) {
  const double e = map.quantity_or(key, Dimension::kDimensionless, 1.0);
  if (!(e > 0.0 && e <= 2.0))
    throw_input("a superquadric exponent must lie in (0, 2] (convex shapes)", map.where(key));
  return e;
}

// A list of three quantities of one dimension, e.g. position: [0 mm, 0 mm, 30 mm].
Vector3d read_vector(const MapReader& map, const std::string& key, Dimension dim) {
  const YAML::Node node = map.at(key);
  if (!node.IsSequence() || node.size() != 3)
    throw_input("expected a list of three values, e.g. [0, 0, -1]", map.where(key));
  Vector3d v;
  for (int i = 0; i < 3; ++i) {
    try {
      v[i] = parse_quantity(text_of(node[i]), dim);
    } catch (const Error& e) {
      throw e.within(map.where(key));
    }
    if (dim == Dimension::kLength && std::abs(v[i]) > kLengthRange.max)
      check_plausible(v[i], kLengthRange, map.where(key));
  }
  return v;
}

Vector3d read_unit_vector(const MapReader& map, const std::string& key, const Vector3d& fallback) {
  if (!map.has(key)) return fallback;
  const Vector3d v = read_vector(map, key, Dimension::kDimensionless);
  if (!(v.norm() > 0) || !v.allFinite())
    throw_input("must be a non-zero direction", map.where(key));
  return v.normalized();
}

IndenterSpec read_indenter(const MapReader& top) {
  IndenterSpec indenter;
  const auto map = section(top, "indenter");
  if (!map) return indenter;
  indenter.shape = map->choice_or("shape", kShapes, indenter.shape);
  switch (indenter.shape) {
    case IndenterShape::kSphere:
      map->allow_only({"shape", "radius", "material", "position", "direction"});
      indenter.radius = map->positive("radius", Dimension::kLength);
      break;
    case IndenterShape::kSuperquadric:
      map->allow_only({"shape", "a", "b", "c", "e1", "e2", "material", "position", "direction"});
      indenter.a = map->positive("a", Dimension::kLength);
      indenter.b = map->positive("b", Dimension::kLength);
      indenter.c = map->positive("c", Dimension::kLength);
      indenter.e1 = read_exponent(*map, "e1");
      indenter.e2 = read_exponent(*map, "e2");
      break;
    case IndenterShape::kFlatPunch:
      map->allow_only({"shape", "radius", "edge_radius", "material", "position", "direction"});
      indenter.radius = map->positive("radius", Dimension::kLength);
      indenter.edge_radius = map->quantity_or("edge_radius", Dimension::kLength, 0.0);
      if (indenter.edge_radius < 0.0 || indenter.edge_radius >= indenter.radius)
        throw_input("must lie in [0, radius)", map->where("edge_radius"));
      break;
    case IndenterShape::kCylinder:
      map->allow_only({"shape", "radius", "length", "material", "position", "direction", "axis"});
      indenter.radius = map->positive("radius", Dimension::kLength);
      indenter.length = map->positive("length", Dimension::kLength);
      break;
  }
  if (map->has("material") && text_of(map->at("material")) != "rigid")
    indenter.material = read_material(map->at("material"), map->where("material"));
  if (map->has("position")) indenter.position = read_vector(*map, "position", Dimension::kLength);
  indenter.direction = read_unit_vector(*map, "direction", indenter.direction);
  indenter.axis = read_unit_vector(*map, "axis", indenter.axis);
  return indenter;
}

// The kinematics decide whether the paper's traction option applies (it is defined for linear
// kinematics: paper eqs 72-80 with a constant K_e).
ContactSpec read_contact(const MapReader& top, Kinematics kinematics,
                         const IndenterSpec& indenter) {
  ContactSpec contact;
  const auto map = section(top, "contact");
  if (!map) return contact;
  map->allow_only(
      {"surface", "solver", "local", "local_support", "local_plies", "traction", "fbar"});
  contact.surface = map->choice_or("surface", kSurfaces, contact.surface);
  contact.solver = map->choice_or("solver", kSolvers, contact.solver);
  contact.local = map->choice_or("local", local_contact_spellings(), contact.local);
  contact.local_support =
      map->choice_or("local_support", local_support_spellings(), contact.local_support);
  contact.local_plies = map->choice_or("local_plies", local_plies_spellings(), contact.local_plies);
  for (const char* key : {"local_support", "local_plies"})
    if (map->has(key) && contact.local != LocalContactModel::kAnisotropic)
      throw_input(std::string("`") + key + "` chooses how `local: anisotropic` is built; set " +
                      "`local: anisotropic` or remove it",
                  map->where(key));
  if (contact.local_support == LocalSupport::kShell && map->has("local_plies") &&
      contact.local_plies != LocalPlies::kResolved)
    throw_input(
        "`local_support: shell` always resolves the plies (its kernel is the exact plate less the "
        "shell's own, both of the same plies); remove `local_plies` or set it to resolved",
        map->where("local_plies"));
  contact.traction = map->choice_or("traction", kTractions, contact.traction);
  contact.fbar = map->choice_or("fbar", boolean_spellings(), contact.fbar);
  if (contact.traction == ContactTraction::kInterpolated && kinematics != Kinematics::kLinear)
    throw_input(
        "the interpolated contact traction (the paper's option) is defined for linear "
        "kinematics only (paper eqs 72-80); set `kinematics: linear` or use "
        "`traction: nodal`",
        map->where("traction"));
  // On the nodal rows the F-bar term is built from the strains' linear map B (face_thickening.hpp).
  if (contact.fbar && contact.traction == ContactTraction::kNodal &&
      kinematics != Kinematics::kLinear)
    throw_input(
        "the F-bar face term of the nodal contact is built for linear kinematics (strains B q); "
        "set `kinematics: linear` or `fbar: false`",
        map->where("fbar"));
  // The power laws' equation F = k alpha^1.5 has no pivot of its own at the start; with nodal
  // gaps the apex row, closed at first touch, supplies it, but the weighted gaps are all open
  // there and the Jacobian is singular (measured on studies/paper_option_cap.yaml).
  if (contact.traction == ContactTraction::kInterpolated &&
      (contact.local == LocalContactModel::kHertz || contact.local == LocalContactModel::kYangSun ||
       contact.local == LocalContactModel::kAnisotropic))
    throw_input(
        "a Hertz-type local contact (hertz, yang_sun, anisotropic) is not available with the "
        "interpolated traction; use `traction: nodal` or `local: none | vam`",
        map->where("local"));
  // Hertz's dent profile (contact/hertz_dent.hpp) is defined for a sphere only.
  if ((contact.local == LocalContactModel::kHertz || contact.local == LocalContactModel::kYangSun ||
       contact.local == LocalContactModel::kAnisotropic) &&
      indenter.shape != IndenterShape::kSphere)
    throw_input("a Hertz-type local law needs a spherical indenter", map->where("local"));
  return contact;
}

// The load section is optional; once written, its magnitude is required (no paper default).
// With a `loads:` list the `load` section may be left out, or give only `steps`.
std::optional<LoadSpec> read_load(const MapReader& top) {
  const auto map = section(top, "load");
  LoadSpec load;
  load.named = read_named_loads(top);
  if (!map) {
    if (load.named.empty()) return std::nullopt;
    load.type = LoadType::kNone;
    return load;
  }
  load.type =
      load.named.empty() || map->has("type") ? map->choice("type", kLoadTypes) : LoadType::kNone;
  switch (load.type) {
    case LoadType::kNone:
      map->allow_only({"steps"});
      break;
    case LoadType::kApexForce:
      map->allow_only({"type", "force", "steps"});
      load.force = map->positive("force", Dimension::kForce);
      break;
    case LoadType::kPressure:
      map->allow_only({"type", "pressure", "steps", "follower"});
      load.pressure = map->positive("pressure", Dimension::kStress);
      load.follower = map->choice_or("follower", boolean_spellings(), load.follower);
      break;
  }
  load.steps = map->integer_or("steps", load.steps);
  if (load.steps < 1) throw_input("must be a whole number >= 1", map->where("steps"));
  return load;
}

// `static:` (docs/case-file.md): natural load stepping (load.steps) or pseudo-arclength.
StaticSettings read_static(const MapReader& top) {
  StaticSettings s;
  const auto map = section(top, "static");
  if (!map) return s;
  map->allow_only({"method", "step", "step_min", "step_max", "parameter_weight", "load_factor_max",
                   "max_steps", "tolerance", "record", "stability"});
  s.method = map->choice_or("method", path_method_spellings(), s.method);
  s.tolerance = map->positive_or("tolerance", Dimension::kDimensionless, s.tolerance);
  if (s.tolerance >= 1e-2) throw_input("must be below 1e-2", map->where("tolerance"));
  s.stability = map->choice_or("stability", boolean_spellings(), s.stability);
  if (s.method == PathMethod::kNatural) {
    for (const char* key :
         {"step", "step_min", "step_max", "parameter_weight", "load_factor_max", "max_steps"})
      if (map->has(key))
        throw_input("only with method: pseudo_arclength (natural steps are load.steps)",
                    map->where(key));
    return s;
  }
  s.step = map->positive_or("step", Dimension::kLength, s.step);
  s.step_min = map->positive_or("step_min", Dimension::kLength, s.step / 1000.0);
  s.step_max = map->positive_or("step_max", Dimension::kLength, 10.0 * s.step);
  if (s.step < s.step_min || s.step > s.step_max)
    throw_input("step must lie in [step_min, step_max] = [" +
                    format_quantity(s.step_min, Dimension::kLength) + ", " +
                    format_quantity(s.step_max, Dimension::kLength) + "]",
                map->where(map->has("step")       ? "step"
                           : map->has("step_min") ? "step_min"
                                                  : "step_max"));
  s.parameter_weight = map->positive_or("parameter_weight", Dimension::kLength, s.parameter_weight);
  s.load_factor_max =
      map->positive_or("load_factor_max", Dimension::kDimensionless, s.load_factor_max);
  s.max_steps = map->integer_or("max_steps", s.max_steps);
  if (s.max_steps < 1) throw_input("must be a whole number >= 1", map->where("max_steps"));
  return s;
}

// static.record (the command resolves the names against the mesh).
std::vector<std::string> read_static_record(const MapReader& top) {
  const auto map = section(top, "static");
  if (!map || !map->has("record")) return {};
  return read_name_list(*map, "record");
}

// The path lands on output.at: pseudo-arclength on path.depths, natural stepping on its grid
// (path.depths, or the steps), so the depths join the list; a depth within 1e-12 of depth_max
// of one already there is that one.
std::vector<double> with_output_depths(const PathSpec& path, const std::vector<double>& at) {
  if (at.empty()) return path.depths;
  std::vector<double> depths = path.method == PathMethod::kNatural ? depth_grid(path) : path.depths;
  depths.insert(depths.end(), at.begin(), at.end());
  std::sort(depths.begin(), depths.end());
  std::vector<double> merged;
  for (double d : depths)
    if (merged.empty() || d - merged.back() > 1e-12 * path.depth_max) merged.push_back(d);
  return merged;
}

MaterialTable read_materials(const MapReader& top) {
  const Material default_material = read_material(top.at("material"), top.where("material"));
  std::vector<Material> named;
  if (top.has("materials")) named = read_material_map(top.at("materials"), top.where("materials"));
  return MaterialTable{default_material, named};
}

// The text of a 1-based line, trimmed, to quote it in a syntax error.
std::string line_text(const std::string& text, int line) {
  std::istringstream in(text);
  std::string current;
  for (int i = 0; i < line; ++i)
    if (!std::getline(in, current)) return "";
  const size_t begin = current.find_first_not_of(" \t");
  const size_t end = current.find_last_not_of(" \t\r");
  return begin == std::string::npos ? "" : current.substr(begin, end - begin + 1);
}

}  // namespace

CaseFile parse_case_file(const std::string& yaml_text, const std::string& file_label) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    const int line = e.mark.line >= 0 ? e.mark.line + 1 : 0;
    // yaml-cpp's messages do not say that tabs are not allowed for indentation: a common slip.
    const bool has_tab = yaml_text.find('\t') != std::string::npos;
    throw_input("invalid YAML: " + e.msg +
                    (has_tab ? " (the file contains tab characters; YAML indentation must use "
                               "spaces)"
                             : ""),
                Where{file_label, "", line_text(yaml_text, line), line});
  }
  if (root.IsNull()) throw_input("the case file is empty", Where{file_label, "", "", 0});
  const MapReader top(root, Where{file_label, "", "", 0});
  top.allow_only({"material", "materials", "laminate", "shell", "mesh", "kinematics", "indenter",
                  "contact", "path", "output", "load", "loads", "supports", "static", "damage",
                  "fixture"});
  top.at("laminate");  // say it is missing before reading the rest
  const MaterialTable materials = read_materials(top);
  const Kinematics kinematics =
      top.choice_or("kinematics", kinematics_spellings(), Kinematics::kNonlinear);
  // Read in file order (the first error found is the one reported), then put together.
  Laminate laminate = read_laminate(top.at("laminate"), top.where("laminate"), materials);
  ShellSpec shell = read_shell(top, has_mesh_file(top));
  FixtureSpec fixture = read_fixture(top, shell);
  MeshSpec mesh = read_mesh(top, shell.type, fixture.type != FixtureType::kNone);
  IndenterSpec indenter = read_indenter(top);
  ContactSpec contact = read_contact(top, kinematics, indenter);
  PathSpec path = read_path(top, contact);
  OutputSpec output = read_output(top, path.depth_max, mesh.symmetry == Symmetry::kQuarter);
  path.depths = with_output_depths(path, output.at);
  std::optional<LoadSpec> load = read_load(top);
  StaticSettings static_run = read_static(top);
  std::vector<std::string> static_record = read_static_record(top);
  std::optional<DamageSpec> damage = read_damage(top, laminate);
  return CaseFile{{{std::move(laminate), std::move(shell), std::move(mesh), kinematics,
                    std::move(load), file_label, std::move(fixture)},
                   std::move(indenter),
                   contact,
                   std::move(path),
                   std::move(damage)},
                  materials.default_material,
                  std::move(output),
                  std::move(static_run),
                  std::move(static_record)};
}

CaseFile read_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!std::filesystem::is_regular_file(path) || !in)
    throw_input("cannot open the case file (does it exist?)", Where{path, "", "", 0});
  std::ostringstream text;
  text << in.rdbuf();
  return parse_case_file(text.str(), path);
}

}  // namespace si
