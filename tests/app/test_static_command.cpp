// End-to-end tests of `shellindent static`: exit codes (0 ok, 2 bad input, 1 failed step), the
// quarter-model refusal for an angle ply, the files written, the table and the progress lines.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_support.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::fresh_dir;
using testing::run_cli;
using testing::write_case;

// A coarse clamped isotropic plate under a centre force: a few hundred dofs, runs in well under
// a second.
std::string tiny_case(const std::string& layup, const std::string& symmetry,
                      const std::string& kinematics, const std::string& material = "steel") {
  return "material: " + material +
         "\n"
         "laminate: {layup: \"" +
         layup +
         "\", ply_thickness: 0.5 mm}\n"
         "shell: {type: flat_circular_plate, radius: 25 mm, edge: clamped}\n"
         "mesh: {size_apex: 4 mm, size_edge: 6 mm, refine_radius: 10 mm, symmetry: " +
         symmetry + "}\nkinematics: " + kinematics +
         "\nload: {type: apex_force, force: 100 N, steps: 2}\n";
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

TEST(StaticCommand, HelpNamesTheOutputs) {
  const auto r = run_cli("static --help");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* part : {"--out", "static.csv", "Example"})
    EXPECT_TRUE(contains(r.output, part)) << part << "\n" << r.output;
}

TEST(StaticCommand, LinearRunWritesCsvJsonVtuAndTheTable) {
  const fs::path dir = fresh_dir("static_ok");
  const fs::path path = write_case(dir, tiny_case("[0]", "quarter", "linear"));
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* part : {"step 2: load factor 1", "deflection_mm", "strain_energy_Nmm"})
    EXPECT_TRUE(contains(r.output, part)) << part << "\n" << r.output;
  for (const char* file : {"static.csv", "static.json", "static.vtu"})
    EXPECT_TRUE(fs::exists(dir / "out" / file)) << file;
  const auto j = nlohmann::json::parse(read_text(dir / "out" / "static.json"));
  EXPECT_EQ(j.at("status"), "completed");
  ASSERT_EQ(j.at("steps").size(), 2u);
  const auto& last = j.at("steps")[1];
  // Whole-shell values of the quarter model: the applied force is the case's 100 N, and the
  // supports carry it (linear run: to roundoff).
  EXPECT_NEAR(last.at("force_N").get<double>(), 100.0, 1e-9);
  EXPECT_NEAR(last.at("reaction_N").get<double>(), 100.0, 1e-6);
  EXPECT_GT(last.at("apex_deflection_mm").get<double>(), 0.0);
  const std::string vtu = read_text(dir / "out" / "static.vtu");
  EXPECT_TRUE(contains(vtu, "Name=\"N\"")) << vtu.substr(0, 2000);
  for (const char* name : {"M", "Q1", "Q2", "membrane_strain", "curvature", "shear_strain_13",
                           "shear_strain_23", "displacement", "director"})
    EXPECT_TRUE(contains(vtu, std::string("Name=\"") + name + "\"")) << name;
  EXPECT_EQ(read_text(dir / "out" / "static.csv").find("load_factor,force_N"), 0u);
}

TEST(StaticCommand, QuarterModelOfAnAnglePlyIsRefused) {
  const fs::path dir = fresh_dir("static_quarter");
  const fs::path path =
      write_case(dir, tiny_case("[45/-45]2S", "quarter", "linear", "paper-carbon-epoxy"));
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "mesh.symmetry")) << r.output;
  EXPECT_TRUE(contains(r.output, "bending-twisting")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(StaticCommand, CaseWithoutALoadSectionIsAnInputError) {
  const fs::path dir = fresh_dir("static_noload");
  const fs::path path = write_case(dir,
                                   "material: steel\n"
                                   "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n");
  const auto r = run_cli("static '" + path.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "load")) << r.output;
}

TEST(StaticCommand, Bernstein4RunsWithAWarning) {
  const fs::path dir = fresh_dir("static_bernstein");
  std::string text = tiny_case("[0]", "quarter", "linear");
  text.replace(text.find("mesh: {"), 7, "mesh: {element: bernstein4, ");
  const fs::path path = write_case(dir, text);
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "warning: mesh.element = bernstein4")) << r.output;
  EXPECT_TRUE(contains(r.output, "patch test")) << r.output;
}

TEST(StaticCommand, FreeEdgeIsRefusedBeforeTheRun) {
  // A free edge is the only edge condition of the schema and leaves rigid-body motions.
  const fs::path dir = fresh_dir("static_free");
  std::string text = tiny_case("[0]", "full", "linear");
  text.replace(text.find("edge: clamped"), 13, "edge: free");
  const fs::path path = write_case(dir, text);
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "shell.edge = 'free'")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// static.record: the mean displacement of a set as columns. The apex set is the node whose
// deflection the run writes anyway, so <set>_uz_mm must be minus apex_deflection_mm in every
// row; the rim (clamped) must not move. An unknown set is refused before anything is made.
TEST(StaticCommand, RecordedSetsAreColumnsAndAnUnknownSetIsRefused) {
  const fs::path dir = fresh_dir("static_record");
  const std::string text = tiny_case("[0]", "full", "linear") + "static: {record: [apex, rim]}\n";
  const fs::path path = write_case(dir, text);
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(read_text(dir / "out" / "static.json"));
  ASSERT_EQ(j.at("steps").size(), 2u);
  for (const auto& step : j.at("steps")) {
    EXPECT_GT(step.at("apex_deflection_mm").get<double>(), 0);
    EXPECT_EQ(step.at("apex_uz_mm").get<double>(), -step.at("apex_deflection_mm").get<double>());
    for (const char* column : {"rim_ux_mm", "rim_uy_mm", "rim_uz_mm"})
      EXPECT_EQ(step.at(column).get<double>(), 0) << column;
  }
  EXPECT_TRUE(
      contains(read_text(dir / "out" / "static.csv"), ",apex_ux_mm,apex_uy_mm,apex_uz_mm,"));
  const fs::path dir2 = fresh_dir("static_record_unknown");
  const fs::path bad =
      write_case(dir2, tiny_case("[0]", "full", "linear") + "static: {record: [tip]}\n");
  const auto r2 = run_cli("static '" + bad.string() + "' --out '" + (dir2 / "out").string() + "'");
  EXPECT_EQ(r2.exit_code, 2) << r2.output;
  EXPECT_TRUE(contains(r2.output, "static.record")) << r2.output;
  EXPECT_TRUE(contains(r2.output, "unknown node set 'tip'")) << r2.output;
  EXPECT_FALSE(fs::exists(dir2 / "out"));
}

TEST(StaticCommand, NonConvergedRunExitsOneAndWritesWhereItStopped) {
  // A 0.04 mm thick cap under 50 kN: far beyond its collapse load, so load control cannot
  // converge; the run must stop with exit 1, say where and why, and keep its steps table.
  const fs::path dir = fresh_dir("static_fail");
  const fs::path path = write_case(dir,
                                   "material: paper-carbon-epoxy\n"
                                   "laminate: {layup: \"[0/90]S\", ply_thickness: 0.01 mm}\n"
                                   "mesh: {size_apex: 2 mm, size_edge: 4 mm, symmetry: quarter}\n"
                                   "load: {type: apex_force, force: 50 kN, steps: 3}\n");
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(contains(r.output, "the run stopped after")) << r.output;
  EXPECT_TRUE(contains(r.output, "no convergence")) << r.output;
  const auto j = nlohmann::json::parse(read_text(dir / "out" / "static.json"));
  EXPECT_EQ(j.at("status"), "failed");
  EXPECT_FALSE(j.at("failure").get<std::string>().empty());
}

// Snap-through from a case file: Sze's hinged cylindrical roof, h = 12.7 (K.Y. Sze, X.H. Liu,
// S.H. Lo, Finite Elements in Analysis and Design 40 (2004) 1551-1569, sec. 3.8(a); data in
// ../shared/benchmarks/nonlinear.md), the quarter model with 8 x 8 mitc4 elements, traced by
// `static.method: pseudo_arclength` through both limit points of the load up to P/Pmax = 1.1.
// Reference (Table 9(a), ABAQUS S4R): the first local maximum P/Pmax = 0.7421 and the local
// minimum 0.1729 of the tabulated path; acceptance as in the verification test
// (test_sze_hinged_roof.cpp): within 1 % of Pmax = 3000 N. Measured: 0.7411 and 0.1735.
std::string hinged_roof_case(const std::string& more_static = "") {
  return "material: {type: isotropic, E: 3102.75 MPa, nu: 0.3}\n"
         "laminate: {layup: \"[0]\", ply_thickness: 12.7 mm}\n"
         "shell: {type: cylindrical_panel, radius: 2540 mm, length: 508 mm, angle: 11.459156 deg,\n"
         "        edge: free}\n"
         "mesh: {size_apex: 31.8 mm, symmetry: quarter}\n"
         "supports: [{on: straight_edges, type: hinged}]\n"
         "loads: [{type: point, on: apex, force: [0 N, 0 N, -3000 N]}]\n"
         "static: {method: pseudo_arclength, step: 0.2 mm, step_max: 0.25 mm,\n"
         "         parameter_weight: 10 mm, load_factor_max: 1.1" +
         more_static + "}\n";
}

TEST(StaticCommand, SzeHingedRoofSnapsThroughBothLimitPoints_SzeLiuLo2004Sec38a) {
  const fs::path dir = fresh_dir("static_roof");
  const fs::path path = write_case(dir, hinged_roof_case());
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "64 mitc4 elements")) << r.output;
  const auto j = nlohmann::json::parse(read_text(dir / "out" / "static.json"));
  EXPECT_EQ(j.at("status"), "completed");
  EXPECT_EQ(j.at("method"), "pseudo_arclength");
  const auto& events = j.at("events");
  ASSERT_EQ(events.size(), 2u) << events.dump(1);
  constexpr double kPmax = 3000;
  for (int i = 0; i < 2; ++i) EXPECT_EQ(events[i].at("type"), "limit_point");
  EXPECT_NEAR(events[0].at("load_factor").get<double>(), 0.7421, 0.01);
  EXPECT_NEAR(events[1].at("load_factor").get<double>(), 0.1729, 0.01);
  EXPECT_NEAR(events[0].at("force_N").get<double>(), 0.7421 * kPmax, 0.01 * kPmax);
  // The path went down between the two and ends on load_factor_max on the far side of the snap
  // (the table's stiffening branch: -W_C from 24 mm at P/Pmax 0.39 to 29.4 mm at 1.08).
  const auto& steps = j.at("steps");
  EXPECT_EQ(steps.back().at("load_factor").get<double>(), 1.1);
  EXPECT_GT(steps.back().at("apex_deflection_mm").get<double>(), 25.0);
  bool fell = false;
  for (const auto& s : steps) fell = fell || s.at("load_factor").get<double>() < 0.2;
  EXPECT_TRUE(fell);
  EXPECT_TRUE(contains(r.output, "limit_point at load factor 0.74")) << r.output;
}

// static.stability on the same roof: the two limit points of the load, located by dp/ds = 0, are
// also the two changes of the negative count of the chart Hessian (0 -> 1, 1 -> 0), located on
// the lowest eigenvalue and classified limit_point (two independent indicators of one point:
// the same load factor to the location tolerance); no bifurcation on the quarter model (its
// symmetric modes only, which the command notes). The steps are stable, then unstable between
// the two, then stable again; a VTU with the critical mode per change.
TEST(StaticCommand, StabilityOfTheHingedRoofMatchesItsLimitPoints) {
  const fs::path dir = fresh_dir("static_roof_stability");
  const fs::path path = write_case(dir, hinged_roof_case(", stability: true"));
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "sees only the modes symmetric")) << r.output;
  const auto j = nlohmann::json::parse(read_text(dir / "out" / "static.json"));
  std::vector<double> limits, changes;
  for (const auto& e : j.at("events")) {
    if (e.at("type") == "limit_point") limits.push_back(e.at("load_factor").get<double>());
    if (e.at("type") != "stability_change") continue;
    EXPECT_EQ(e.at("criticality"), "limit_point") << e.dump();
    changes.push_back(e.at("load_factor").get<double>());
  }
  ASSERT_EQ(limits.size(), 2u) << j.at("events").dump(1);
  ASSERT_EQ(changes.size(), 2u) << j.at("events").dump(1);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(changes[i], limits[i], 1e-6) << "event " << i;
  // stable <=> lowest eigenvalue > 0; stable, unstable, stable again: two switches.
  const auto& steps = j.at("steps");
  int switches = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const bool stable = steps[i].at("stable").get<bool>();
    EXPECT_EQ(stable, steps[i].at("lowest_eigenvalue").get<double>() > 0) << steps[i].dump();
    if (i > 0 && stable != steps[i - 1].at("stable").get<bool>()) ++switches;
  }
  EXPECT_TRUE(steps.front().at("stable").get<bool>());
  EXPECT_TRUE(steps.back().at("stable").get<bool>());
  EXPECT_EQ(switches, 2);
  EXPECT_TRUE(fs::exists(dir / "out" / "static_stability_01.vtu"));
  EXPECT_TRUE(fs::exists(dir / "out" / "static_stability_02.vtu"));
  EXPECT_TRUE(contains(read_text(dir / "out" / "static_stability_01.vtu"), "critical_mode"));
  EXPECT_TRUE(contains(read_text(dir / "out" / "static.csv"), ",stable,lowest_eigenvalue\n"));
}

TEST(StaticCommand, OutputDirectoryThatIsAFileIsRefusedBeforeTheRun) {
  const fs::path dir = fresh_dir("static_outfile");
  const fs::path path = write_case(dir, tiny_case("[0]", "quarter", "linear"));
  { std::ofstream(dir / "afile") << "x"; }
  const auto r = run_cli("static '" + path.string() + "' --out '" + (dir / "afile").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "--out")) << r.output;
  EXPECT_FALSE(contains(r.output, "step 1")) << r.output;
}

}  // namespace
}  // namespace si
