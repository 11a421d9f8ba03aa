// Supports and loads on named sets, from case files: the built-in meshes' side names, beam theory
// (a cantilever strip under an edge load, a clamped-clamped strip under pressure, nu = 0 so that
// the plate strip is exactly a beam), Navier's simply supported plate, the same model from a Gmsh
// file and from the built-in generator, graded plate and panel meshes, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "../model/mesh_test_support.hpp"
#include "../model/msh_test_writer.hpp"
#include "../verification/point_load_support.hpp"
#include "model/mesh_quality.hpp"
#include "model/shell_model.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

using testing::expect_input_error;

const std::string kSteelHead =
    "material: steel\n"
    "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n";

ShellModel build(const std::string& body) {
  return build_shell_model(parse_case_file(kSteelHead + body, "named.yaml"));
}

// A case of one isotropic ply (E, nu) 1 mm thick, linear, one load step.
std::string isotropic(double nu, const std::string& body) {
  return "material: {type: isotropic, E: 70000 MPa, nu: " + std::to_string(nu) +
         "}\nlaminate: {layup: \"[0]\", ply_thickness: 1 mm}\nkinematics: linear\n" + body;
}

TEST(NamedSets, PlateSidesPanelSidesAndRimAreExact) {
  const ShellModel plate = build(
      "shell: {type: rectangular_plate, length_x: 40 mm, length_y: 20 mm}\nmesh: {size_apex: 5 "
      "mm}\n");
  const Mesh& m = plate.mesh;
  testing::expect_set_is(m, "x-", [](const Vector3d& p) { return p.x() == -20; });
  testing::expect_set_is(m, "x+", [](const Vector3d& p) { return p.x() == 20; });
  testing::expect_set_is(m, "y-", [](const Vector3d& p) { return p.y() == -10; });
  testing::expect_set_is(m, "y+", [](const Vector3d& p) { return p.y() == 10; });
  const ShellModel quarter = build(
      "shell: {type: rectangular_plate, length_x: 40 mm, length_y: 20 mm}\nmesh: {size_apex: 5 "
      "mm, symmetry: quarter}\n");
  testing::expect_set_is(quarter.mesh, "x+", [](const Vector3d& p) { return p.x() == 20; });
  EXPECT_EQ(quarter.mesh.node_sets.count("x-"), 0u);
  const ShellModel panel = build(
      "shell: {type: cylindrical_panel, radius: 50 mm, length: 40 mm, angle: 60 deg}\n"
      "mesh: {size_apex: 5 mm}\n");
  const double edge_x = 50 * std::sin(std::acos(-1.0) / 6);
  testing::expect_set_is(panel.mesh, "x-",
                         [&](const Vector3d& p) { return std::abs(p.x() + edge_x) < 1e-9; });
  testing::expect_set_is(panel.mesh, "x+",
                         [&](const Vector3d& p) { return std::abs(p.x() - edge_x) < 1e-9; });
  testing::expect_set_is(panel.mesh, "y-", [](const Vector3d& p) { return p.y() == -20; });
  testing::expect_set_is(panel.mesh, "y+", [](const Vector3d& p) { return p.y() == 20; });
  const ShellModel cap = build("mesh: {size_apex: 2 mm, size_edge: 4 mm}\n");
  testing::expect_set_is(cap.mesh, "rim",
                         [](const Vector3d& p) { return std::abs(p.z()) < 1e-12; });
}

// Tip deflection of a cantilever under an end load P: P L^3 / (3 E I) + P L / (k G A) (Timoshenko
// beam, k = 5/6); nu = 0 makes the plate strip a beam.
TEST(NamedSets, CantileverStripUnderEdgeLoad_BeamTheory) {
  const double L = 100, b = 10, E = 70000, q = 0.01;  // q in N/mm along the free end
  const testing::StaticRun run = testing::run_static_case(
      isotropic(0.0,
                "shell: {type: rectangular_plate, length_x: 100 mm, length_y: 10 mm, edge: free}\n"
                "mesh: {size_apex: 2 mm}\n"
                "supports: [{on: x-, type: clamped}]\n"
                "loads: [{type: edge, on: x+, force_per_length: [0 N/mm, 0 N/mm, -0.01 N/mm]}]\n"
                "load: {steps: 1}\n"));
  const double P = q * b, I = b / 12.0, G = E / 2;
  const double expected = P * L * L * L / (3 * E * I) + P * L / (5.0 / 6.0 * G * b);
  const Mesh& m = run.model.mesh;
  for (int n : m.node_sets.at("x+"))
    EXPECT_NEAR(testing::deflection(run, n), expected, 3e-3 * expected);
  EXPECT_NEAR(run.steps.back().reaction_force.z(), P, 1e-9 * P);
}

// Tip deflection of a cantilever bent by an end moment M: M L^2 / (2 E I), no shear term (pure
// bending; nu = 0 makes the plate strip a beam). The moment about -y lifts the free end. Once as
// a moment per length along the free end (consistent nodal moments), once as a moment at each of
// its nodes with the same total: a node-by-node split that is not the consistent one (every node
// the same share) changes only the end's local twist, so the mean deflection agrees to 1 %.
TEST(NamedSets, CantileverStripUnderEndMoment_BeamTheory) {
  const double L = 100, b = 10, E = 70000, m = 0.01;  // m in N mm/mm along the free end
  const std::string strip =
      "shell: {type: rectangular_plate, length_x: 100 mm, length_y: 10 mm, edge: free}\n"
      "mesh: {size_apex: 2 mm}\n"
      "supports: [{on: x-, type: clamped}]\n"
      "load: {steps: 1}\n";
  const testing::StaticRun edge = testing::run_static_case(isotropic(
      0.0, strip + "loads: [{type: edge, on: x+, moment_per_length: [0 N*mm/mm, -0.01 N*mm/mm, "
                   "0 N*mm/mm]}]\n"));
  const double M = m * b, I = b / 12.0;
  const double expected = -M * L * L / (2 * E * I);  // testing::deflection is -u_z
  const std::vector<int>& tip = edge.model.mesh.node_sets.at("x+");
  for (int n : tip) EXPECT_NEAR(testing::deflection(edge, n), expected, 3e-3 * std::abs(expected));
  EXPECT_NEAR(edge.steps.back().reaction_force.norm(), 0, 1e-12);

  const std::string per_node = std::to_string(-M / tip.size());
  const testing::StaticRun nodal = testing::run_static_case(
      isotropic(0.0, strip + "loads: [{type: moment, on: x+, moment: [0 N*mm, " + per_node +
                         " N*mm, 0 N*mm]}]\n"));
  double mean = 0;
  for (int n : tip) mean += testing::deflection(nodal, n) / tip.size();
  EXPECT_NEAR(mean, expected, 1e-2 * std::abs(expected));
}

// Mid-span deflection of a clamped-clamped beam under a uniform load w: w L^4 / (384 E I) +
// w L^2 / (8 k G A), w = p b.
TEST(NamedSets, StripClampedOnTwoEdgesFreeOnTwo_BeamTheory) {
  const double L = 60, b = 12, E = 70000, p = 1e-4;
  const testing::StaticRun run = testing::run_static_case(
      isotropic(0.0,
                "shell: {type: rectangular_plate, length_x: 60 mm, length_y: 12 mm}\n"
                "mesh: {size_apex: 1 mm}\n"
                "supports: [{on: x-, type: clamped}, {on: x+, type: clamped}, {on: y-, type: free},"
                " {on: y+, type: free}]\n"
                "loads: [{type: pressure, pressure: 0.0001 MPa}]\nload: {steps: 1}\n"));
  const double w = p * b, I = b / 12.0, G = E / 2;
  const double expected = w * std::pow(L, 4) / (384 * E * I) + w * L * L / (8 * 5.0 / 6.0 * G * b);
  EXPECT_NEAR(testing::deflection(run, run.model.apex_node()), expected, 3e-3 * expected);
}

// Navier's series for a simply supported square plate under uniform pressure q (Reissner-Mindlin:
// w_mn = q_mn / (D pi^4 k^4) + q_mn / (kappa G t pi^2 k^2), k^2 = (m/a)^2 + (n/b)^2,
// q_mn = 16 q / (pi^2 m n)), at the centre.
double navier_centre(double a, double t, double E, double nu, double q) {
  const double pi = std::acos(-1.0), D = E * t * t * t / (12 * (1 - nu * nu));
  const double shear = 5.0 / 6.0 * E / (2 * (1 + nu)) * t;
  double w = 0;
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const double k2 = (m * m + n * n) / (a * a), qmn = 16 * q / (pi * pi * m * n);
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;  // sin(m pi/2) sin(n pi/2)
      w += sign * (qmn / (D * std::pow(pi, 4) * k2 * k2) + qmn / (shear * pi * pi * k2));
    }
  return w;
}

TEST(NamedSets, SimplySupportedPlateUnderPressure_NavierAndLegacyEdge) {
  const std::string common =
      "mesh: {size_apex: 2 mm}\nloads: [{type: pressure, pressure: 0.001 MPa}]\nload: {steps: 1}\n";
  const testing::StaticRun named = testing::run_static_case(isotropic(
      0.3, "shell: {type: rectangular_plate, length_x: 100 mm, length_y: 100 mm}\n" + common +
               "supports: [{on: x-, type: simply_supported}, {on: x+, type: simply_supported}, "
               "{on: y-, type: simply_supported}, {on: y+, type: simply_supported}]\n"));
  const double expected = navier_centre(100, 1, 70000, 0.3, 0.001);
  const double w = testing::deflection(named, named.model.apex_node());
  EXPECT_NEAR(w, expected, 1e-2 * expected);
  // The same plate with the single `shell.edge` of earlier versions: the same constraints.
  const testing::StaticRun legacy = testing::run_static_case(
      isotropic(0.3,
                "shell: {type: rectangular_plate, length_x: 100 mm, length_y: 100 mm, edge: "
                "simply_supported}\n" +
                    common));
  ASSERT_EQ(legacy.state.size(), named.state.size());
  for (size_t n = 0; n < named.state.size(); ++n)
    EXPECT_NEAR((named.state[n].u - legacy.state[n].u).norm(), 0, 1e-12 * expected);
}

// The built-in plate written as a Gmsh file with its sides as physical curves and read back: the
// same model, the same answer to round-off.
TEST(NamedSets, GmshFileOfTheBuiltInPlateGivesTheSameResults) {
  const std::string body =
      "mesh: {size_apex: 4 mm}\nsupports: [{on: x-, type: clamped}, {on: y-, type: hinged}]\n"
      "loads: [{type: edge, on: x+, force_per_length: [0 N/mm, 0 N/mm, -0.1 N/mm]},"
      " {type: point, on: apex, force: [0 N, 0 N, -2 N]}]\nload: {steps: 1}\n";
  const testing::StaticRun builtin = testing::run_static_case(
      isotropic(0.3,
                "shell: {type: rectangular_plate, length_x: 40 mm, length_y: 24 mm, edge: "
                "free}\n" +
                    body));
  const auto dir = std::filesystem::temp_directory_path() / "shellindent_named_sets";
  std::filesystem::create_directories(dir);
  testing::write_msh41(builtin.model.mesh, {"x-", "x+", "y-", "apex"},
                       (dir / "plate.msh").string());
  std::string yaml = isotropic(0.3, "shell: {edge: free}\n" + body);
  const std::string sized = "mesh: {size_apex: 4 mm}";
  yaml.replace(yaml.find(sized), sized.size(),
               "mesh: {file: " + (dir / "plate.msh").string() + "}");
  const testing::StaticRun imported = testing::run_static_case(yaml);
  ASSERT_EQ(imported.state.size(), builtin.state.size());
  double scale = 0;
  for (const auto& s : builtin.state) scale = std::max(scale, s.u.norm());
  ASSERT_GT(scale, 0);
  for (size_t n = 0; n < builtin.state.size(); ++n)
    EXPECT_NEAR((imported.state[n].u - builtin.state[n].u).norm(), 0, 1e-12 * scale) << n;
}

TEST(NamedSets, GradedPlateAndPanelRefineUnderTheIndenter) {
  const ShellModel plate = build(
      "shell: {type: rectangular_plate, length_x: 150 mm, length_y: 100 mm}\n"
      "mesh: {grading: graded, size_apex: 0.5 mm, size_edge: 4 mm, refine_radius: 10 mm}\n");
  const Mesh& m = plate.mesh;
  EXPECT_NO_THROW(check_mesh(m));
  double worst_aspect = 0;
  for (int e = 0; e < m.num_elements(); ++e) {
    const Vector3d c = testing::centroid(m, e);
    const double h = testing::longest_edge(m, e);
    if (std::abs(c.x()) < 10 && std::abs(c.y()) < 10) {
      EXPECT_LE(h, 0.5 * (1 + 1e-3));
    }
    EXPECT_LE(h, 4 * (1 + 1e-2));
    worst_aspect = std::max(worst_aspect, element_quality(m, e).aspect_ratio);
  }
  EXPECT_LE(worst_aspect, 8.0 + 1e-9);  // size_edge / size_apex
  // Far fewer elements than the uniform mesh at size_apex (300 x 200).
  EXPECT_LT(m.num_elements(), 60000 / 4);
  EXPECT_NEAR(m.nodes[plate.apex_node()].norm(), 0, 1e-12);
  // Neighbouring element sizes along the centre line change smoothly.
  std::vector<double> xs;
  for (int n : m.node_sets.at("y-")) xs.push_back(m.nodes[n].x());
  std::sort(xs.begin(), xs.end());
  for (size_t k = 2; k < xs.size(); ++k) {
    const double ratio = (xs[k] - xs[k - 1]) / (xs[k - 1] - xs[k - 2]);
    EXPECT_LT(std::max(ratio, 1 / ratio), 1.25) << xs[k];
  }
  const ShellModel panel = build(
      "shell: {type: cylindrical_panel, radius: 100 mm, length: 80 mm, angle: 60 deg}\n"
      "mesh: {grading: graded, size_apex: 0.5 mm, size_edge: 3 mm, refine_radius: 8 mm, "
      "symmetry: quarter}\n");
  EXPECT_NO_THROW(check_mesh(panel.mesh));
  EXPECT_NEAR(panel.mesh.nodes[panel.apex_node()].z(), 100, 1e-12);
  for (int n = 0; n < panel.mesh.num_nodes(); ++n)
    EXPECT_NEAR(std::hypot(panel.mesh.nodes[n].x(), panel.mesh.nodes[n].z()), 100, 1e-10);
}

void expect_case_error(const std::string& yaml, const std::vector<std::string>& parts) {
  expect_input_error([&] { build_shell_model(parse_case_file(yaml, "named.yaml")); }, parts);
}

TEST(NamedSets, RefusesBadEntriesNamingKeyLineAndValue) {
  const std::string plate =
      kSteelHead + "shell: {type: rectangular_plate, length_x: 40 mm, length_y: 20 mm}\n";
  expect_case_error(
      plate + "supports:\n  - {on: x_, type: clamped}\n",
      {"named.yaml:5:", "supports[0].on = 'x_'", "no set 'x_'", "did you mean", "x+"});
  expect_case_error(
      plate + "supports:\n  - {on: x-, type: clamped}\n  - {on: x-, type: hinged}\n",
      {"named.yaml:6:", "conflicting supports on 'x-'", "clamped (line 5)", "hinged"});
  expect_case_error(plate + "supports:\n  - {on: x-, type: displacement, u_q: 1 mm}\n",
                    {"named.yaml:5:", "u_q", "did you mean 'u_x'"});
  expect_case_error(plate + "supports:\n  - {on: x-, type: fixed}\n",
                    {"named.yaml:5:", "supports[0].type = 'fixed'"});
  expect_case_error(plate + "supports:\n  - {on: x-, type: displacement, theta_1: 2 deg}\n",
                    {"supports[0].on", "rotation must be 0"});
  expect_case_error(plate + "loads:\n  - {type: edge, on: apex, force_per_length: [0, 0, 1 N]}\n",
                    {"loads[0].force_per_length", "force per length"});
  expect_case_error(plate +
                        "loads:\n  - {type: edge, on: apex, force_per_length: [0 N/mm, 0 "
                        "N/mm, 1 N/mm]}\n",
                    {"loads[0].on = 'apex'", "no element side"});
  expect_case_error(plate + "loads:\n  - {type: edge, on: x+}\n",
                    {"named.yaml:5:", "loads[0]", "force_per_length", "moment_per_length"});
  expect_case_error(plate + "loads:\n  - {type: moment, on: x+, moment: [0 N, 1 N, 0 N]}\n",
                    {"loads[0].moment", "moment", "N*mm"});
  expect_case_error(
      plate + "loads:\n  - {type: moment, on: x+, moment: [0 N*mm, 0 N*mm, 1 N*mm]}\n",
      {"named.yaml:5:", "loads[0].on = 'x+'", "drilling"});
  expect_case_error(plate +
                        "loads:\n  - {type: edge, on: x+, moment_per_length: [0 N*mm/mm, 0 "
                        "N*mm/mm, 1 N*mm/mm]}\n",
                    {"named.yaml:5:", "loads[0].on = 'x+'", "drilling"});
  expect_case_error(plate +
                        "loads:\n  - {type: moment, on: x+, at: [0 mm, 0 mm, 0 mm], moment: [0 "
                        "N*mm, 1 N*mm, 0 N*mm]}\n",
                    {"named.yaml:5:", "exactly one of `on`"});
  expect_case_error(plate + "loads:\n  - {type: point, on: corner, force: [0 N, 0 N, 1 N]}\n",
                    {"named.yaml:5:", "loads[0].on = 'corner'", "no set 'corner'"});
  expect_case_error(kSteelHead + "mesh: {grading: uniform}\n", {"mesh.grading", "always graded"});
  expect_case_error(kSteelHead + "mesh: {file: no_such.msh}\n", {"mesh.file", "cannot open"});
  // A physical group the case names but the file does not have.
  const std::string fixture =
      std::string(SHELLINDENT_SOURCE_DIR) + "/tests/model/data/gmsh_plate_41.msh";
  expect_case_error(
      kSteelHead + "mesh: {file: " + fixture + "}\nsupports:\n  - {on: clampd, type: clamped}\n",
      {"named.yaml:5:", "no set 'clampd'", "did you mean 'clamped'", "loaded edge"});
}

TEST(NamedSets, MeshFileGroupsCarrySupportsAndLoads) {
  const std::string fixture =
      std::string(SHELLINDENT_SOURCE_DIR) + "/tests/model/data/gmsh_plate_41_binary.msh";
  const ShellModel m = build("mesh: {file: " + fixture +
                             "}\nshell: {edge: free}\nsupports: [{on: clamped, type: clamped}]\n"
                             "loads: [{type: edge, on: loaded edge, force_per_length: [0 N/mm, 0 "
                             "N/mm, 1 N/mm]}, {type: pressure, on: plate, pressure: 1 MPa}]\n");
  ASSERT_EQ(m.supports.size(), 1u);
  EXPECT_EQ(m.supports[0].node_set, "clamped");
  EXPECT_EQ(m.loads.lines.size(), 2u);  // the side x = 2 has two element sides
  ASSERT_EQ(m.loads.pressures.size(), 1u);
  EXPECT_EQ(m.loads.pressures[0].elements.size(), 8u);
  EXPECT_EQ(m.mesh.node_sets.at("edge").size(), 12u);  // the boundary of the 4 x 2 grid
}

}  // namespace
}  // namespace si
