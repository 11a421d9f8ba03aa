// The bad-input catalogue (issue 13): case files, study files, data files and command-line flags
// that must each be refused by the `shellindent` executable with exit code 2 and a message naming
// the key or option (and the file and line where there is one), with nothing written: the
// directory the command runs in holds afterwards exactly the files the test put there. One ctest
// per row. Rows marked "issue 13 item N" failed on main 2a11fc3 (a crash, a wrong exit code, a
// message without the key or line, or files written).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "io/output_lock.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

struct BadInput {
  std::string name;
  std::map<std::string, std::string> files;  // written into the row's directory first
  std::string args;                          // after the executable; runs in that directory
  std::vector<std::string> expected;         // phrases the message must contain
  int exit_code = 2;
  std::size_t max_output = 20000;  // bytes: a message quotes a value, never all of a huge one
  bool lock_out = false;           // hold the lock of out/ while the command runs
};

// Two lines every case needs; a row's own lines start at line 3.
const std::string kHead =
    "material: paper-carbon-epoxy\n"
    "laminate: {layup: \"[0/90]S\", ply_thickness: 0.475 mm}\n";
// A coarse mesh (line 3) for rows whose error is found once the model is built.
const std::string kCoarse = kHead + "mesh: {size_apex: 2 mm, size_edge: 4 mm}\n";

BadInput run_row(std::string name, std::string yaml, std::vector<std::string> expected) {
  return {std::move(name),
          {{"case.yaml", std::move(yaml)}},
          "run case.yaml --out out",
          std::move(expected)};
}

BadInput static_row(std::string name, std::string yaml, std::vector<std::string> expected) {
  BadInput r = run_row(std::move(name), std::move(yaml), std::move(expected));
  r.args = "static case.yaml --out out";
  return r;
}

BadInput cli_row(std::string name, std::string args, std::vector<std::string> expected,
                 std::map<std::string, std::string> files = {}) {
  return {std::move(name), std::move(files), std::move(args), std::move(expected)};
}

// A study over case.yaml with `vary` (and more) as given.
BadInput sweep_row(std::string name, std::string study, std::vector<std::string> expected,
                   std::string base = kHead) {
  return {std::move(name),
          {{"case.yaml", std::move(base)}, {"study.yaml", "base: case.yaml\n" + study}},
          "sweep study.yaml --out out",
          std::move(expected)};
}

const std::string kData = "x,y\n1,2\n2,4.1\n3,5.9\n4,8.2\n5,9.8\n";

BadInput fit_row(std::string name, std::string args, std::vector<std::string> expected,
                 std::string data = kData) {
  return cli_row(std::move(name), "fit data.csv --json out/fit.json " + args, std::move(expected),
                 {{"data.csv", std::move(data)}});
}

std::string repeat(const std::string& s, std::size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (std::size_t i = 0; i < n; ++i) out += s;
  return out;
}

std::vector<BadInput> case_file_rows() {
  const std::string deep = "[" + repeat("(", 100000) + "0" + repeat(")", 100000) + "]";
  const std::string huge(1000000, '9');
  return {
      run_row("EmptyFile", "", {"case.yaml", "the case file is empty"}),
      run_row("InvalidYaml", "material: [steel\n", {"case.yaml:", "invalid YAML"}),
      run_row("TabIndentation", "material: steel\nlaminate:\n\tlayup: x\n",
              {"case.yaml:", "tab characters"}),
      run_row("MissingLaminate", "material: paper-carbon-epoxy\n",
              {"case.yaml", "missing key 'laminate'"}),
      run_row("MissingMaterial", "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml", "missing key 'material'"}),
      run_row("UnknownTopLevelKey", kHead + "meshh: {element: mitc4}\n",
              {"case.yaml:3", "meshh", "did you mean 'mesh'"}),
      run_row("KeyGivenTwice", kHead + "kinematics: linear\nkinematics: nonlinear\n",
              {"case.yaml:4", "kinematics", "key given twice"}),
      // Issue 16: damage onset. A criterion whose strengths a ply's material lacks (steel has
      // none), a negative strength, a threshold without G_IIc (t300-914c has no toughness), a
      // negative impact energy: refused when read, naming the material, key and criterion.
      run_row(
          "DamageCriterionWithoutStrengths",
          "material: steel\nlaminate: {layup: \"[0/90]S\", ply_thickness: 0.475 mm}\n"
          "damage:\n  criteria: [max_stress, hashin]\n",
          {"case.yaml:4", "damage.criteria[0]", "material 'steel' has no X_T", "maximum stress"}),
      run_row("DamageNegativeStrength",
              "material: {type: isotropic, E: 70 GPa, nu: 0.3, strengths: {X_T: -300 MPa}}\n"
              "laminate: {layup: \"[0/90]S\", ply_thickness: 0.475 mm}\n"
              "damage: {criteria: [hashin]}\n",
              {"case.yaml:1", "X_T", "-300 MPa"}),
      run_row("DamageThresholdWithoutToughness",
              "material: t300-914c\nlaminate: {layup: \"[0/90]S\", ply_thickness: 0.475 mm}\n"
              "damage: {threshold: {stiffness: olsson}}\n",
              {"case.yaml:3", "damage.threshold", "has no G_IIc"}),
      run_row("DamageNegativeImpactEnergy", kHead + "damage: {impact_energies: [1 J, -2 J]}\n",
              {"case.yaml:3", "damage.impact_energies[1]", "-2 J", "must be > 0"}),
      run_row("DamageUnknownCriterion", kHead + "damage: {criteria: [hashn]}\n",
              {"case.yaml:3", "damage.criteria[0]", "hashn"}),
      run_row("DamageUnknownFacePressure",
              kHead + "damage: {criteria: [hashin], face_pressure: herz}\n",
              {"case.yaml:3", "damage.face_pressure", "herz", "hertz"}),
      run_row("DamageNegativePatchRadius",
              kHead + "damage: {criteria: [hashin], patch_radius: -1 mm}\n",
              {"case.yaml:3", "damage.patch_radius", "-1 mm", ">= 0"}),
      run_row("UnknownLibraryMaterial",
              "material: steell\nlaminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material", "did you mean 'steel'"}),
      run_row("InlineMaterialWithoutType",
              "material: {E: 200 GPa, nu: 0.3}\nlaminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.type", "missing key 'type'"}),
      run_row("PoissonRatioOfHalf",
              "material: {type: isotropic, E: 200 GPa, nu: 0.5}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.nu", "'0.5'"}),
      run_row("NegativeModulus",
              "material: {type: isotropic, E: -200 GPa, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "'-200 GPa'"}),
      // Issue 13 item 7: E = 1e-300 GPa passed the reader and failed later naming no key.
      run_row("ModulusFarTooSmall",
              "material: {type: isotropic, E: 1e-300 GPa, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "'1e-300 GPa'", "not a plausible value"}),
      run_row("ModulusFarTooLarge",
              "material: {type: isotropic, E: 1e9 GPa, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "not a plausible value"}),
      run_row("ModulusWithoutUnit",
              "material: {type: isotropic, E: 200, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "missing unit"}),
      run_row("ModulusWithALengthUnit",
              "material: {type: isotropic, E: 200 mm, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "wrong unit"}),
      // Issue 13 item 7: hexadecimal floats were accepted silently.
      run_row("HexadecimalModulus",
              "material: {type: isotropic, E: 0x1p6 GPa, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "'0x1p6 GPa'", "hexadecimal"}),
      run_row("NanModulus",
              "material: {type: isotropic, E: nan GPa, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "not a number"}),
      run_row("InfiniteModulus",
              "material: {type: isotropic, E: inf GPa, nu: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.E", "not a number"}),
      run_row("OrthotropicWithoutNu23",
              "material: {type: orthotropic, E1: 130 GPa, E2: 10 GPa, E3: 10 GPa, G12: 6 GPa,\n"
              "           G13: 3 GPa, G23: 6 GPa, nu12: 0.3, nu13: 0.5}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:1", "material.nu23", "missing key 'nu23'"}),
      run_row("OrthotropicNotPositiveDefinite",
              "material: {type: orthotropic, E1: 130 GPa, E2: 10 GPa, E3: 10 GPa, G12: 6 GPa,\n"
              "           G13: 3 GPa, G23: 6 GPa, nu12: 5, nu13: 0.5, nu23: 0.3}\n"
              "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:", "material.nu12", "'5'"}),
      run_row("MaterialsEntryIsAList", kHead + "materials:\n  foam: [1, 2]\n",
              {"case.yaml:4", "materials.foam"}),
      run_row("LayupEmptyPly",
              "material: steel\nlaminate: {layup: \"[45//0]\", ply_thickness: 1 mm}\n",
              {"case.yaml:2", "laminate.layup", "empty ply at character 5"}),
      // Issue 13 item 1: deep nesting overflowed the parser's stack (SIGSEGV).
      run_row("LayupNestedTooDeep",
              "material: steel\nlaminate: {layup: \"" + deep + "\", ply_thickness: 1 mm}\n",
              {"case.yaml:2", "laminate.layup", "nested deeper than 64 levels"}),
      run_row("LayupCountAboveLimit",
              "material: steel\nlaminate: {layup: \"[0_1001]\", ply_thickness: 1 mm}\n",
              {"case.yaml:2", "laminate.layup", "repetition count above 1000"}),
      run_row("LayupAngleBeyond360",
              "material: steel\nlaminate: {layup: \"[400]\", ply_thickness: 1 mm}\n",
              {"case.yaml:2", "laminate.layup", "angle beyond"}),
      run_row("LayupUnclosed",
              "material: steel\nlaminate: {layup: \"[0/90\", ply_thickness: 1 mm}\n",
              {"case.yaml:2", "laminate.layup", "missing ']'"}),
      run_row("PlyThicknessNegative",
              "material: steel\nlaminate: {layup: \"[0]\", ply_thickness: -1 mm}\n",
              {"case.yaml:2", "laminate.ply_thickness", "must be positive"}),
      run_row("PlyThicknessImplausiblySmall",
              "material: steel\nlaminate: {layup: \"[0]\", ply_thickness: 1e-300 mm}\n",
              {"case.yaml:2", "laminate.ply_thickness", "not a plausible value"}),
      run_row("PlyThicknessImplausiblyLarge",
              "material: steel\nlaminate: {layup: \"[0]\", ply_thickness: 5000 m}\n",
              {"case.yaml:2", "laminate.ply_thickness", "'5000 m'", "not a plausible value"}),
      run_row("PlyThicknessWithoutUnit",
              "material: steel\nlaminate: {layup: \"[0]\", ply_thickness: 0.475}\n",
              {"case.yaml:2", "laminate.ply_thickness", "missing unit"}),
      run_row("LaminateWithoutLayupOrPlies", "material: steel\nlaminate: {reference: mid}\n",
              {"case.yaml:2", "laminate", "give either"}),
      run_row("EmptyPlyList", "material: steel\nlaminate: {plies: []}\n",
              {"case.yaml:2", "laminate.plies", "non-empty list"}),
      run_row("PlyOfUndefinedMaterial",
              "material: steel\nlaminate:\n  plies:\n    - {thickness: 1 mm}\n"
              "    - {material: cork, thickness: 1 mm}\n",
              {"case.yaml:5", "laminate.plies[1].material", "undefined material 'cork'"}),
      run_row("PlyOfZeroThickness",
              "material: steel\nlaminate:\n  plies:\n    - {thickness: 0 mm}\n",
              {"case.yaml:4", "laminate.plies[0].thickness", "must be positive"}),
      run_row("ReferenceSurfaceUnknown",
              "material: steel\nlaminate: {layup: \"[0]\", ply_thickness: 1 mm, "
              "reference: sideways}\n",
              {"case.yaml:2", "laminate.reference", "expected mid, bottom, top"}),
      run_row("ReferenceSurfaceOutsideTheLaminate",
              "material: steel\nlaminate: {layup: \"[0]\", ply_thickness: 1 mm, "
              "reference: 10 mm}\n",
              {"case.yaml:2", "laminate.reference", "within the laminate"}),
      run_row("ShellTypeUnknown", kHead + "shell: {type: dome}\n",
              {"case.yaml:3", "shell.type", "unknown value"}),
      run_row("CapWithoutRadius", kHead + "shell: {type: spherical_cap, base_radius: 25 mm}\n",
              {"case.yaml:3", "shell.radius", "missing key 'radius'"}),
      // Issue 13 item 8: a base radius equal to the radius was found only by the mesher,
      // without the line and with the value reformatted.
      run_row("CapBaseRadiusEqualToRadius",
              kHead + "shell: {type: spherical_cap, base_radius: 80.9 mm, radius: 80.9 mm}\n",
              {"case.yaml:3", "shell.base_radius", "'80.9 mm'", "must be smaller"}),
      run_row("CapBaseRadiusAboveRadius",
              kHead + "shell: {type: spherical_cap, base_radius: 90 mm, radius: 80.9 mm}\n",
              {"case.yaml:3", "shell.base_radius", "must be smaller"}),
      run_row("PanelAngleAbove360",
              kHead + "shell: {type: cylindrical_panel, radius: 50 mm, length: 50 mm, "
                      "angle: 400 deg}\n",
              {"case.yaml:3", "shell.angle", "must not exceed 360"}),
      run_row("EdgeConditionUnknown",
              kHead + "shell: {type: flat_circular_plate, radius: 25 mm, edge: welded}\n",
              {"case.yaml:3", "shell.edge", "unknown value"}),
      run_row("FreeEdge",
              kCoarse + "shell: {type: flat_circular_plate, radius: 25 mm, edge: free}\n",
              {"case.yaml:4", "shell.edge", "'free'", "free edge"}),
      run_row("SimplySupportedCap",
              kCoarse + "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, "
                        "edge: simply_supported}\n",
              {"case.yaml:4", "shell.edge", "simply_supported needs a flat plate"}),
      run_row("ElementUnknown", kHead + "mesh: {element: mitc9}\n",
              {"case.yaml:3", "mesh.element", "unknown value"}),
      run_row("MeshSizeZero", kHead + "mesh: {size_apex: 0 mm}\n",
              {"case.yaml:3", "mesh.size_apex", "must be positive"}),
      run_row("MeshSizeAsksForTooManyElements", kHead + "mesh: {size_apex: 0.001 mm}\n",
              {"case.yaml:3", "mesh.size_apex", "'0.001 mm'", "elements"}),
      run_row("QuarterModelOfAnAnglePly",
              "material: paper-carbon-epoxy\n"
              "laminate: {layup: \"[45/-45]S\", ply_thickness: 0.475 mm}\n"
              "mesh: {size_apex: 2 mm, size_edge: 4 mm,\n       symmetry: quarter}\n",
              {"case.yaml:4", "mesh.symmetry", "specially orthotropic"}),
      run_row("KinematicsUnknown", kHead + "kinematics: elastic\n",
              {"case.yaml:3", "kinematics", "unknown value"}),
      run_row("IndenterShapeUnknown", kHead + "indenter: {shape: cone}\n",
              {"case.yaml:3", "indenter.shape", "unknown value"}),
      run_row("SphereWithoutRadius", kHead + "indenter: {shape: sphere}\n",
              {"case.yaml:3", "indenter.radius", "missing key 'radius'"}),
      run_row("PunchEdgeRadiusTooLarge",
              kHead + "indenter: {shape: flat_punch, radius: 5 mm, edge_radius: 5 mm}\n",
              {"case.yaml:3", "indenter.edge_radius", "[0, radius)"}),
      run_row("SuperquadricExponentAbove2",
              kHead + "indenter: {shape: superquadric, a: 5 mm, b: 5 mm, c: 5 mm, e1: 3}\n",
              {"case.yaml:3", "indenter.e1", "(0, 2]"}),
      run_row("ZeroDirection",
              kHead + "indenter: {shape: sphere, radius: 5 mm, direction: [0, 0, 0]}\n",
              {"case.yaml:3", "indenter.direction", "non-zero direction"}),
      // Issue 13 item 3: an indenter moving away from the shell passed through the laminate and
      // "touched" the outer face from inside, exit 0.
      run_row("IndenterMovingAwayFromTheShell",
              kCoarse + "indenter: {shape: sphere, radius: 12.7 mm,\n"
                        "           direction: [0, 0, 1]}\n",
              {"case.yaml:5", "indenter.direction", "'[0, 0, 1]'", "travels away"}),
      run_row("IndenterStartingInsideTheShell",
              kCoarse + "indenter: {shape: sphere, radius: 12.7 mm,\n"
                        "           position: [0 mm, 0 mm, 0 mm]}\n",
              {"case.yaml:5", "indenter.position", "starts inside"}),
      run_row(
          "IndenterBesideTheShell",
          kCoarse + "indenter: {shape: sphere, radius: 1 mm, position: [500 mm, 0 mm, 10 mm]}\n",
          {"case.yaml:4", "indenter.position", "never touches"}),
      run_row("PositionOfTwoValues",
              kHead + "indenter: {shape: sphere, radius: 5 mm, position: [0 mm, 0 mm]}\n",
              {"case.yaml:3", "indenter.position", "list of three"}),
      run_row("PositionImplausiblyFar",
              kHead + "indenter: {shape: sphere, radius: 5 mm, position: [0 mm, 0 mm, 1e9 m]}\n",
              {"case.yaml:3", "indenter.position", "not a plausible value"}),
      run_row("IndenterMaterialUnknown",
              kHead + "indenter: {shape: sphere, radius: 5 mm, material: adamantium}\n",
              {"case.yaml:3", "indenter.material", "adamantium"}),
      run_row("ContactSurfaceUnknown", kHead + "contact: {surface: inner}\n",
              {"case.yaml:3", "contact.surface", "unknown value"}),
      run_row("InterpolatedTractionNeedsLinearKinematics",
              kHead + "contact: {traction: interpolated}\n",
              {"case.yaml:3", "contact.traction", "linear kinematics"}),
      run_row("FbarOnNodalContactNeedsLinearKinematics", kHead + "contact: {fbar: true}\n",
              {"case.yaml:3", "contact.fbar", "linear kinematics"}),
      run_row(
          "ElasticFaceHomogenisedPlies",
          kHead + "contact: {local: anisotropic, local_support: shell, local_plies: homogenised}\n",
          {"case.yaml:3", "contact.local_plies", "always resolves"}),
      run_row("LocalLawMisspelt", kHead + "contact: {local: hertzz}\n",
              {"case.yaml:3", "contact.local", "did you mean 'hertz'"}),
      run_row("PathMethodUnknown", kHead + "path: {method: arc}\n",
              {"case.yaml:3", "path.method", "unknown value"}),
      run_row("DepthMaxNegative", kHead + "path: {depth_max: -1 mm}\n",
              {"case.yaml:3", "path.depth_max", "must be positive"}),
      run_row("DepthMaxNotANumber", kHead + "path: {depth_max: nan mm}\n",
              {"case.yaml:3", "path.depth_max", "not a number"}),
      run_row("StepAboveDepthMax", kHead + "path: {depth_max: 1 mm, step: 2 mm}\n",
              {"case.yaml:3", "path.step", "exceeds depth_max"}),
      run_row("StepMinAboveStepMax",
              kHead + "path: {depth_max: 1 mm, step: 0.1 mm, step_min: 0.5 mm, step_max: 0.2 mm}\n",
              {"case.yaml:3", "path.step_min", "exceeds step_max"}),
      run_row("DepthsNotIncreasing", kHead + "path: {depth_max: 1 mm, depths: [0.5 mm, 0.2 mm]}\n",
              {"case.yaml:3", "path.depths[1]", "increase strictly"}),
      run_row("DepthBeyondDepthMax", kHead + "path: {depth_max: 1 mm, depths: [2 mm]}\n",
              {"case.yaml:3", "path.depths[0]", "(0, depth_max"}),
      // Issue 15: the stability of the points.
      run_row("StabilityNotABoolean", kHead + "path: {stability: yes please}\n",
              {"case.yaml:3", "path.stability", "unknown value"}),
      run_row("StabilityWithALocalLaw",
              kHead + "contact: {local: hertz}\npath: {stability: true}\n",
              {"case.yaml:4", "path.stability", "contact.local: none"}),
      // Issue 15 item 4: the onset of nonlinearity's fraction.
      run_row("NonlinearityFractionZero", kHead + "path: {nonlinearity_fraction: 0}\n",
              {"case.yaml:3", "path.nonlinearity_fraction", "fraction in (0, 1)"}),
      run_row("NonlinearityFractionNegativePercent",
              kHead + "path: {nonlinearity_fraction: -5 %}\n",
              {"case.yaml:3", "path.nonlinearity_fraction", "fraction in (0, 1)"}),
      run_row("NonlinearityFractionWithAUnit", kHead + "path: {nonlinearity_fraction: 5 mm}\n",
              {"case.yaml:3", "path.nonlinearity_fraction", "without a unit"}),
      // Issue 15 item 2: the imperfection seeded from a critical mode.
      run_row("ImperfectionWithoutStability",
              kHead + "path: {imperfection: {mode: 1, amplitude: 0.01 mm}}\n",
              {"case.yaml:3", "path.imperfection", "path.stability: true"}),
      run_row("ImperfectionModeBeyondTheComputed",
              kHead + "path: {stability: true, imperfection: {mode: 11, amplitude: 0.01 mm}}\n",
              {"case.yaml:3", "path.imperfection.mode", "11", "beyond the modes",
               "1 (the lowest) to 10"}),
      run_row("ImperfectionModeZero",
              kHead + "path: {stability: true, imperfection: {mode: 0, amplitude: 0.01 mm}}\n",
              {"case.yaml:3", "path.imperfection.mode", "beyond the modes"}),
      run_row("ImperfectionAmplitudeNegative",
              kHead + "path: {stability: true, imperfection: {mode: 1, amplitude: -0.01 mm}}\n",
              {"case.yaml:3", "path.imperfection.amplitude", "-0.01 mm"}),
      run_row("ImperfectionAmplitudeMissing",
              kHead + "path: {stability: true, imperfection: {mode: 1}}\n",
              {"case.yaml:3", "path.imperfection", "amplitude"}),
      run_row("ImperfectionAmplitudeWithoutUnit",
              kHead + "path: {stability: true, imperfection: {mode: 1, amplitude: 0.01}}\n",
              {"case.yaml:3", "path.imperfection.amplitude", "unit"}),
      // Issue 15 item 2: branch switching at the first bifurcation.
      run_row("BranchSwitchWithoutStability", kHead + "path: {branch_switch: {direction: 1}}\n",
              {"case.yaml:3", "path.branch_switch", "path.stability: true"}),
      run_row("BranchSwitchOnNaturalContinuation",
              kHead + "path: {method: natural, stability: true, branch_switch: {}}\n",
              {"case.yaml:3", "path.branch_switch", "pseudo_arclength"}),
      run_row("BranchSwitchOnAnImperfectShell",
              kHead + "path: {stability: true, imperfection: {mode: 1, amplitude: 0.01 mm},"
                      " branch_switch: {}}\n",
              {"case.yaml:3", "path.branch_switch", "not both"}),
      run_row("BranchSwitchDirectionTwo",
              kHead + "path: {stability: true, branch_switch: {direction: 2}}\n",
              {"case.yaml:3", "path.branch_switch.direction", "1 (along the critical mode) or -1"}),
      run_row("ImperfectionUnknownKey",
              kHead + "path: {stability: true, imperfection: {mode: 1, amplitud: 0.01 mm}}\n",
              {"case.yaml:3", "amplitud", "did you mean 'amplitude'"}),
      // Issue 19 item 1: the discretisation error's tolerance.
      run_row("MeshToleranceAboveOne", kHead + "mesh: {tolerance: 2}\n",
              {"case.yaml:3", "mesh.tolerance", "fraction in (0, 1)"}),
      run_row("MeshToleranceWithAUnit", kHead + "mesh: {tolerance: 1 mm}\n",
              {"case.yaml:3", "mesh.tolerance", "without a unit"}),
      run_row("VtuEveryNegative", kHead + "output: {vtu_every: -1}\n",
              {"case.yaml:3", "output.vtu_every", ">= 0"}),
      run_row("VtuEveryNotWhole", kHead + "output: {vtu_every: 1.5}\n",
              {"case.yaml:3", "output.vtu_every", "whole number"}),
      run_row("OutputFormatUnknown", kHead + "output: {formats: [csv, pdf]}\n",
              {"case.yaml:3", "output.formats[1]", "unknown value"}),
      run_row("OutputFormatsNotAList", kHead + "output: {formats: csv}\n",
              {"case.yaml:3", "output.formats", "expected a list"}),
      // Issue 13 item 8: a 1 MB value was echoed whole (17 s for 100 MB).
      [&] {
        BadInput r =
            run_row("HugeValueIsQuotedShort",
                    "material: steel\nlaminate: {layup: \"[0]\", ply_thickness: " + huge + " mm}\n",
                    {"case.yaml:2", "laminate.ply_thickness", "'99999", "...'"});
        r.max_output = 2000;
        return r;
      }(),
      [&] {  // longer than YAML's 1024 characters for a plain key: invalid YAML, quoted short
        BadInput r = run_row("HugeKeyIsQuotedShort", kHead + huge + ": 1\n",
                             {"case.yaml:3", "'99999", "...'", "invalid YAML"});
        r.max_output = 2000;
        return r;
      }(),
      [&] {
        BadInput r =
            run_row("LongUnknownKeyIsQuotedShort", kHead + std::string(1000, 'k') + ": 1\n",
                    {"case.yaml:3", "unknown key 'kkkk", "...'"});
        r.max_output = 2000;
        return r;
      }(),
      run_row("ListAsKey", kHead + "? [a, b]\n: 1\n", {"case.yaml:3", "unknown key"}),
      run_row("MapAsKey", kHead + "? {a: 1}\n: 1\n", {"case.yaml:3", "unknown key"}),
      static_row("StaticWithoutLoad", kHead, {"case.yaml", "load", "needs a `load` section"}),
      static_row("LoadTypeUnknown", kHead + "load: {type: torque}\n",
                 {"case.yaml:3", "load.type", "unknown value"}),
      static_row("LoadForceNegative", kHead + "load: {type: apex_force, force: -1 kN}\n",
                 {"case.yaml:3", "load.force", "must be positive"}),
      static_row("LoadForceImplausible", kHead + "load: {type: apex_force, force: 1e-30 N}\n",
                 {"case.yaml:3", "load.force", "not a plausible value"}),
      static_row("LoadStepsZero", kHead + "load: {type: apex_force, force: 1 kN, steps: 0}\n",
                 {"case.yaml:3", "load.steps", ">= 1"}),
      static_row("StaticStepWithNaturalMethod",
                 kHead + "load: {type: apex_force, force: 1 kN}\nstatic: {step: 1 mm}\n",
                 {"case.yaml:4", "static.step", "pseudo_arclength"}),
      static_row("StaticMethodUnknown",
                 kHead + "load: {type: apex_force, force: 1 kN}\nstatic: {method: riks}\n",
                 {"case.yaml:4", "static.method", "riks"}),
      static_row("PressureWithAForceUnit", kHead + "load: {type: pressure, pressure: 1 kN}\n",
                 {"case.yaml:3", "load.pressure", "wrong unit"}),
  };
}

std::vector<BadInput> command_line_rows() {
  const std::string deep = "'[" + repeat("(", 50000) + "0" + repeat(")", 50000) + "]'";
  const std::string ok_case = kCoarse + "path: {depth_max: 0.1 mm}\n";
  std::vector<BadInput> rows = {
      // Issue 13 item 2: --threads 100000 crashed in libgomp; -1 blamed `indenter`.
      cli_row("ThreadsNegative", "run case.yaml --out out --threads -1", {"--threads", "'-1'"},
              {{"case.yaml", ok_case}}),
      cli_row("ThreadsFarAboveTheMachine", "run case.yaml --out out --threads 100000",
              {"--threads", "'100000'"}, {{"case.yaml", ok_case}}),
      cli_row("StaticThreadsFarAboveTheMachine", "static case.yaml --out out --threads 30000",
              {"--threads", "'30000'"},
              {{"case.yaml", kCoarse + "load: {type: apex_force, force: 1 kN}\n"}}),
      cli_row("ThreadsNotANumber", "run case.yaml --out out --threads many", {"--threads"},
              {{"case.yaml", ok_case}}),
      cli_row("CaseFileMissing", "run missing.yaml --out out", {"missing.yaml"}),
      // Issue 13 item 9: --resume without a checkpoint made an empty output directory.
      cli_row("ResumeWithoutCheckpoint", "run case.yaml --out out --resume",
              {"--resume", "nothing to resume"}, {{"case.yaml", ok_case}}),
      cli_row("OutIsAFile", "run case.yaml --out case.yaml", {"--out", "'case.yaml'"},
              {{"case.yaml", ok_case}}),
      cli_row("StaticOutIsAFile", "static case.yaml --out case.yaml", {"--out"},
              {{"case.yaml", kCoarse + "load: {type: apex_force, force: 1 kN}\n"}}),
      cli_row("UnknownOption", "run case.yaml --outt out", {"--outt"}, {{"case.yaml", ok_case}}),
      // Issue 13 item 21: a bare `shellindent` said only "A subcommand is required".
      cli_row("NoCommandListsTheCommands", "", {"commands:", "run", "sweep", "layup"}),
      cli_row("MistypedCommandSuggestsTheClosest", "runn case.yaml",
              {"'runn'", "did you mean 'run'"}),
      cli_row("CliLayupUnclosed", "layup '[0/90'", {"missing ']'"}),
      // Issue 13 item 1, from the command line.
      cli_row("CliLayupNestedTooDeep", "layup " + deep, {"nested deeper than 64 levels"}),
      cli_row("CliLayupCountAboveLimit", "layup '[0_1001]'", {"repetition count above 1000"}),
      cli_row("LayupHexadecimalAngle", "layup '[0x10]'", {"lay-up '[0x10]'"}),
      cli_row("SectionUnknownMaterial",
              "section --layup '[0/90]' --material unobtainium --ply-thickness '1 mm'",
              {"--material", "unobtainium"}),
      cli_row("SectionPlyThicknessNegative", "section --layup '[0/90]' --ply-thickness '-1 mm'",
              {"--ply-thickness", "'-1 mm'"}),
      cli_row("SectionPlyThicknessHexadecimal",
              "section --layup '[0/90]' --ply-thickness '0x1p-2 mm'",
              {"--ply-thickness", "hexadecimal"}),
      cli_row("SectionBadLayup", "section --layup '[0/]' --ply-thickness '1 mm'",
              {"--layup", "empty ply"}),
      cli_row("SectionVamOrderZero",
              "section --layup '[0/90]' --ply-thickness '1 mm' --vam-order 0", {"--vam-order"}),
      cli_row("SectionReferenceUnknown",
              "section --layup '[0/90]' --ply-thickness '1 mm' --reference sideways",
              {"--reference", "sideways"}),
      fit_row("FitColumnMissing", "--model power --x depth --y y", {"data.csv", "no such column"}),
      // Issue 13 item 7: a NaN range bound.
      fit_row("FitRangeNan", "--x x --y y --model power --range nan:5", {"--range", "'nan:5'"}),
      fit_row("FitRangeHexadecimal", "--x x --y y --model power --range 0x1:5",
              {"--range", "'0x1:5'"}),
      fit_row("FitRangeInfinite", "--x x --y y --model power --range 1:inf", {"--range"}),
      fit_row("FitRangeReversed", "--x x --y y --model power --range 5:1",
              {"--range", "lower end"}),
      fit_row("FitRangeEmpty", "--x x --y y --model power --range 100:200",
              {"--range", "no points"}),
      fit_row("FitModelUnknown", "--x x --y y --model quadratic", {"--model", "quadratic"}),
      fit_row("FitDegreeNotANumber", "--x x --y y --model poly --degree many", {"--degree"}),
      fit_row("FitCellNotANumber", "--x x --y y --model power", {"data.csv:3", "not a number"},
              "x,y\n1,2\n2,abc\n3,6\n"),
      fit_row("FitCellNan", "--x x --y y --model power", {"data.csv:3", "not a"},
              "x,y\n1,2\n2,nan\n3,6\n"),
      fit_row("FitCellHexadecimal", "--x x --y y --model power", {"data.csv:3", "0x10"},
              "x,y\n1,2\n2,0x10\n3,6\n"),
      fit_row("FitRowTooShort", "--x x --y y --model power", {"data.csv:3", "fields"},
              "x,y\n1,2\n2\n3,6\n"),
      fit_row("FitEmptyFile", "--x x --y y --model power", {"data.csv", "no header"}, ""),
      fit_row("FitHeaderDuplicated", "--x x --y y --model power", {"data.csv:1", "appears twice"},
              "x,x\n1,2\n"),
      cli_row("SweepJobsZero", "sweep study.yaml -j 0 --out out", {"-j", "'0'"},
              {{"case.yaml", kHead},
               {"study.yaml", "base: case.yaml\nvary: {kinematics: [linear]}\n"}}),
      cli_row("SweepJobsFarAboveTheMachine", "sweep study.yaml -j 100000 --out out",
              {"-j", "'100000'"},
              {{"case.yaml", kHead},
               {"study.yaml", "base: case.yaml\nvary: {kinematics: [linear]}\n"}}),
      // Issue 13 item 6: a list as a key under vary was an internal error (exit 3).
      sweep_row("SweepListAsVaryKey", "vary:\n  ? [a, b]\n  : [1, 2]\n",
                {"study.yaml:3", "vary", "dotted case-file key"}),
      sweep_row("SweepVaryKeyMisspelt", "vary:\n  mesh.size_apx: [1 mm]\n",
                {"mesh.size_apx", "did you mean 'size_apex'"}),
      sweep_row("SweepVaryValueNotAList", "vary:\n  kinematics: linear\n",
                {"study.yaml:3", "vary.kinematics", "non-empty list"}),
      sweep_row("SweepNothingToVary", "vary: {}\n", {"study.yaml", "nothing to vary"}),
      sweep_row(
          "SweepZipOfUnequalLists",
          "vary:\n  kinematics: [linear, nonlinear]\n  mesh.size_apex: [1 mm]\ncombine: zip\n",
          {"vary.mesh.size_apex", "equal length"}),
      sweep_row("SweepFitRangeNan", "vary: {kinematics: [linear]}\nfit: {range: \"nan:5\"}\n",
                {"study.yaml:3", "fit.range", "not a finite decimal"}),
      cli_row("SweepBaseMissing", "sweep study.yaml --out out",
              {"study.yaml:1", "base", "'missing.yaml'", "cannot open"},
              {{"study.yaml", "base: missing.yaml\nvary: {kinematics: [linear]}\n"}}),
      sweep_row("SweepCaseOfBadValue", "vary:\n  laminate.ply_thickness: [1 mm, -1 mm]\n",
                {"case 2", "laminate.ply_thickness", "must be positive"}),
      // A sweep reads each case's path.json (item 18: output.formats is honoured).
      sweep_row("SweepWithoutJsonOutput", "vary: {kinematics: [linear]}\n",
                {"output.formats", "must include json"}, kHead + "output: {formats: [csv]}\n"),
  };
  // Issue 13 item 6: 8 keys x 25 values allocated until bad_alloc after 43 s.
  std::string vary = "vary:\n";
  for (const char* key :
       {"mesh.size_apex", "mesh.size_edge", "mesh.refine_radius", "laminate.ply_thickness",
        "indenter.radius", "path.depth_max", "path.step", "shell.radius"}) {
    vary += std::string("  ") + key + ": [";
    for (int i = 1; i <= 25; ++i) vary += (i > 1 ? ", " : "") + std::to_string(i) + " mm";
    vary += "]\n";
  }
  rows.push_back(sweep_row(
      "SweepProductTooLarge", vary,
      {"study.yaml", "vary", "1.526e+11 cases", "mesh.size_apex (25)", "shell.radius (25)"}));
  // Issue 13 item 5: an unwritable output directory was found after the solve (exit 3).
  if (fs::is_directory("/proc/self")) {
    rows.push_back(cli_row("OutNotWritable", "run case.yaml --out /proc/self",
                           {"--out", "'/proc/self'", "cannot write"}, {{"case.yaml", ok_case}}));
    rows.push_back(cli_row("OutputDirNotWritable", "run case.yaml",
                           {"case.yaml:5", "output.dir", "cannot write"},
                           {{"case.yaml", kCoarse + "path: {depth_max: 0.1 mm}\n"
                                                    "output: {dir: /proc/self}\n"}}));
    BadInput s = static_row("StaticOutputDirNotWritable",
                            kCoarse + "load: {type: apex_force, force: 1 kN}\n", {"--out"});
    s.args = "static case.yaml --out /proc/self";
    rows.push_back(s);
  }
  // Issue 13 item 14: a second run into a directory in use raced on the same temporary files.
  BadInput locked = cli_row("OutputDirectoryInUse", "run case.yaml --out out",
                            {"--out", "another shellindent run"}, {{"case.yaml", ok_case}});
  locked.lock_out = true;
  rows.push_back(locked);
  BadInput locked_static =
      cli_row("StaticOutputDirectoryInUse", "static case.yaml --out out",
              {"--out", "another shellindent run"},
              {{"case.yaml", kCoarse + "load: {type: apex_force, force: 1 kN}\n"}});
  locked_static.lock_out = true;
  rows.push_back(locked_static);
  BadInput locked_sweep = cli_row(
      "SweepOutputDirectoryInUse", "sweep study.yaml --out out",
      {"--out", "another shellindent run"},
      {{"case.yaml", kHead}, {"study.yaml", "base: case.yaml\nvary: {kinematics: [linear]}\n"}});
  locked_sweep.lock_out = true;
  rows.push_back(locked_sweep);
  return rows;
}

std::vector<BadInput> all_rows() {
  std::vector<BadInput> rows = case_file_rows();
  for (BadInput& r : command_line_rows()) rows.push_back(std::move(r));
  return rows;
}

// Every file under `dir` (relative paths), to compare before and after.
std::set<std::string> files_under(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    out.insert(fs::relative(e.path(), dir).string() + (e.is_directory() ? "/" : ""));
  return out;
}

testing::CliResult run_in(const fs::path& dir, const std::string& args) {
  const std::string cmd =
      "cd '" + dir.string() + "' && '" + SHELLINDENT_EXE + "' " + args + " 2>&1";
  testing::CliResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;  // -1: killed by a signal
  return r;
}

// gtest prints a parameter of a failed test: its name, not its bytes.
void PrintTo(const BadInput& row, std::ostream* os) {
  *os << row.name;
}

class BadInputCatalogue : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputCatalogue, ExitsTwoNamingTheKeyAndWritesNothing) {
  const BadInput& row = GetParam();
  const fs::path dir = testing::fresh_dir("catalogue_" + row.name);
  for (const auto& [name, text] : row.files) std::ofstream(dir / name, std::ios::binary) << text;
  int lock_fd = -1;
  if (row.lock_out) {  // as a running shellindent holds it (io/output_lock.hpp)
    fs::create_directories(dir / "out");
    lock_fd = ::open((dir / "out" / kOutputLockName).c_str(), O_RDWR | O_CREAT, 0644);
    ASSERT_GE(lock_fd, 0);
    ASSERT_EQ(::flock(lock_fd, LOCK_EX | LOCK_NB), 0);
  }
  const std::set<std::string> before = files_under(dir);
  const testing::CliResult r = run_in(dir, row.args);
  if (lock_fd >= 0) ::close(lock_fd);
  const std::string shown = r.output.substr(0, 3000);
  EXPECT_EQ(r.exit_code, row.exit_code) << shown;
  for (const std::string& part : row.expected)
    EXPECT_TRUE(testing::contains(r.output, part)) << "missing '" << part << "' in:\n" << shown;
  EXPECT_LE(r.output.size(), row.max_output) << shown;
  EXPECT_FALSE(testing::contains(r.output, "internal error")) << shown;
  EXPECT_EQ(files_under(dir), before) << "the command wrote files:\n" << shown;
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Rows, BadInputCatalogue, ::testing::ValuesIn(all_rows()),
                         [](const ::testing::TestParamInfo<BadInput>& row_info) {
                           return row_info.param.name;
                         });

// The catalogue is the acceptance: at least 100 rows.
TEST(BadInputCatalogueSize, HasAtLeastAHundredRows) {
  EXPECT_GE(all_rows().size(), 100u);
}

}  // namespace
}  // namespace si
