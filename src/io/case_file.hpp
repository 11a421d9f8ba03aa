// The one case-file schema of shellindent (docs/case-file.md): a YAML file describing the
// laminate, the shell, the mesh, the indenter, contact, the load path and the output. Reading
// converts every quantity to internal units (mm, MPa, N, deg) and validates it, so the solvers
// downstream receive only values they can use. Defaults of the optional sections are the source
// paper's case: a clamped spherical cap (base radius 25 mm, R = 80.9 mm) indented by a 12.7 mm
// rigid sphere on its outer face, geometrically nonlinear, to 10 mm depth by pseudo-arclength.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contact/local_support.hpp"
#include "core/linalg.hpp"
#include "material/material.hpp"
#include "model/symmetry.hpp"
#include "section/laminate.hpp"
#include "shell/kinematics.hpp"

namespace si {

enum class ShellType { kSphericalCap, kFlatCircularPlate, kRectangularPlate, kCylindricalPanel };
enum class EdgeCondition { kClamped, kHinged, kSimplySupported, kFree };

// Geometry of the shell mid-surface; which lengths are used depends on `type`.
struct ShellSpec {
  ShellType type = ShellType::kSphericalCap;
  double base_radius = 25.0;  // mm, spherical cap: radius of the base circle (plan view)
  double radius = 80.9;       // mm, cap: sphere radius; flat plate: plate radius;
                              //     cylindrical panel: cylinder radius
  double length_x = 0;        // mm, rectangular plate
  double length_y = 0;        // mm, rectangular plate
  double length = 0;          // mm, cylindrical panel: axial length
  double angle_deg = 0;       // cylindrical panel: opening angle
  EdgeCondition edge = EdgeCondition::kClamped;
};

// mitc4 = MITC4 + EAS-4 membrane (the default), mitc4-plain = MITC4 with the bilinear membrane,
// bernstein4 = the paper's element (src/shell/shell_element.hpp).
enum class ElementType { kMitc4, kMitc4Plain, kBernstein4 };

// Mesh size grades from size_apex at the indentation point to size_edge beyond refine_radius.
struct MeshSpec {
  ElementType element = ElementType::kMitc4;
  double size_apex = 0.5;       // mm
  double size_edge = 2.0;       // mm
  double refine_radius = 13.0;  // mm, measured from the indentation point in plan
  Symmetry symmetry = Symmetry::kFull;
};

enum class IndenterShape { kSphere, kSuperquadric, kFlatPunch, kCylinder };

// A rigid indenter unless `material` is given. Which fields are used depends on `shape`.
struct IndenterSpec {
  IndenterShape shape = IndenterShape::kSphere;
  double radius = 12.7;        // mm, sphere, flat punch, cylinder
  double edge_radius = 0;      // mm, flat punch: rounding of the punch edge (0 = sharp)
  double length = 0;           // mm, cylinder: axial length
  double a = 0, b = 0, c = 0;  // mm, superquadric semi-axes along x1, x2, x3
  // Superquadric exponents (Barr 1981): (|x/a|^(2/e2) + |y/b|^(2/e2))^(e2/e1) + |z/c|^(2/e1) = 1;
  // e1 = e2 = 1 is an ellipsoid, smaller values are boxier. 0 < e <= 2 keeps it convex.
  double e1 = 1, e2 = 1;
  std::optional<Material> material;  // empty: rigid
  // Pose (contact/indenter.hpp IndenterPose). Position of the reference point (sphere,
  // super-quadric and cylinder centre, flat-punch tip) at travel 0, mm; empty: on the apex
  // normal, clear of the shell. The depth is the travel after first touch, found automatically.
  std::optional<Vector3d> position;
  Vector3d direction{0, 0, -1};  // direction of travel (normalised when read)
  Vector3d axis{0, 1, 0};        // cylinder axis
};

enum class ContactSurface { kOuter, kMid };
enum class ContactSolver { kKinsol, kActiveSet };
enum class LocalContactModel { kNone, kHertz, kYangSun, kVam, kAnisotropic };

// Contact traction: nodal Lagrange multipliers (forces), or the paper's interpolated traction
// with weighted gaps (analysis/interpolated_contact.hpp; linear kinematics only).
enum class ContactTraction { kNodal, kInterpolated };

struct ContactSpec {
  ContactSurface surface = ContactSurface::kOuter;  // outer = top face of the laminate
  ContactSolver solver = ContactSolver::kKinsol;
  LocalContactModel local = LocalContactModel::kNone;
  // local: anisotropic only (contact/local_support.hpp).
  LocalSupport local_support = LocalSupport::kHalfSpace;
  LocalPlies local_plies = LocalPlies::kHomogenised;
  ContactTraction traction = ContactTraction::kNodal;
  bool fbar = false;  // the paper's F-bar coupling term; needs traction: interpolated
};

enum class PathMethod { kNatural, kPseudoArclength };

// Indentation depth path; all lengths in mm.
struct PathSpec {
  PathMethod method = PathMethod::kPseudoArclength;
  double depth_max = 10.0;
  double step = 0.1;
  double step_min = 1e-4;      // default: step / 1000
  double step_max = 1.0;       // default: min(10 step, depth_max)
  std::vector<double> depths;  // optional explicit depths to stop at, increasing, <= depth_max
};

enum class OutputFormat { kCsv, kJson, kVtu };

struct OutputSpec {
  std::string dir = "results/";
  int vtu_every = 10;  // write a VTU file every n converged steps; 0 = never
  std::vector<OutputFormat> formats{OutputFormat::kCsv, OutputFormat::kVtu};
};

enum class LoadType { kApexForce, kPressure };

// A load-controlled run (`shellindent static`): the load grows from 0 to its full value in
// `steps` equal increments. No contact: the indenter, contact and path sections are not used.
struct LoadSpec {
  LoadType type = LoadType::kApexForce;
  double force = 0;       // N, apex_force: total force along -z at the apex node (the whole shell;
                          //    a quarter model carries a quarter of it)
  double pressure = 0;    // MPa, pressure: on every element, acting against the director (inwards
                          //    on the cap's convex side, i.e. towards -z at the apex)
  int steps = 10;         // >= 1
  bool follower = false;  // pressure only: follows the deformed surface
};

struct CaseFile {
  Laminate laminate;
  Material material;  // the top-level `material:`, the default ply material
  ShellSpec shell;
  MeshSpec mesh;
  Kinematics kinematics = Kinematics::kNonlinear;
  IndenterSpec indenter;
  ContactSpec contact;
  PathSpec path;
  OutputSpec output;
  std::optional<LoadSpec> load;  // only for load-controlled runs
  std::string file;              // the file (or label) the case was read from
};

// Reads and validates a case file. Every error is an input si::Error naming the file and, where
// they exist, the dotted key, the value as written and the 1-based line (a missing file or an
// empty one has no key or line; a missing key has no value).
CaseFile read_case_file(const std::string& path);

// As read_case_file, from text; `file_label` stands for the file name in messages.
CaseFile parse_case_file(const std::string& yaml_text, const std::string& file_label);

}  // namespace si
