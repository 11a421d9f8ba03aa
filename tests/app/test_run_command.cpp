// End-to-end tests of `shellindent run`: the files and columns written, the table, exit codes
// for bad input (indenter that never touches, starts inside, bad radius) and the kept points of
// a run that stops early.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_test_support.hpp"
#include "io/path_results.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::fresh_dir;
using testing::run_cli;
using testing::write_case;

// A coarse quarter of the paper's cap; `indenter` and `extra` replace or add sections.
std::string cap_case(const std::string& kinematics, const std::string& indenter,
                     const std::string& path) {
  return "material: paper-carbon-epoxy\n"
         "laminate: {layup: \"[0/0]2S\", ply_thickness: 0.475 mm}\n"
         "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
         "mesh: {size_apex: 1.5 mm, size_edge: 4 mm, refine_radius: 8 mm, symmetry: quarter}\n"
         "kinematics: " +
         kinematics + "\nindenter: " + indenter + "\npath: " + path + "\noutput: {vtu_every: 2}\n";
}

TEST(RunCommand, LinearPathWritesTableCsvJsonAndVtu) {
  const fs::path dir = fresh_dir("run_linear");
  const fs::path c = write_case(dir, cap_case("linear", "{shape: sphere, radius: 12.7 mm}",
                                              "{method: natural, depth_max: 1 mm, step: 0.25 mm}"));
  const auto r = run_cli("run '" + c.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "linear fast path")) << r.output;
  const std::string csv = testing::read_file(dir / "out" / "path.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), path_csv_header());
  EXPECT_EQ(csv.substr(0, 16), "depth_mm,force_N");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6);  // header + depths 0, 0.25, ..., 1
  const auto json = nlohmann::json::parse(testing::read_file(dir / "out" / "path.json"));
  EXPECT_EQ(json["status"], "completed");
  EXPECT_EQ(json["points"].size(), 5u);
  EXPECT_GT(json["points"][4]["force_N"].get<double>(), 0.0);
  EXPECT_TRUE(fs::exists(dir / "out" / "path_0000.vtu"));
  EXPECT_TRUE(fs::exists(dir / "out" / "path_0004.vtu"));
  EXPECT_TRUE(contains(testing::read_file(dir / "out" / "path_0004.vtu"), "contact_pressure"));
  EXPECT_TRUE(contains(testing::read_file(dir / "out" / "path.pvd"), "path_0002.vtu"));
}

TEST(RunCommand, IndenterBesideTheShellIsRefused) {
  const fs::path dir = fresh_dir("run_miss");
  const fs::path c = write_case(
      dir, cap_case("linear", "{shape: sphere, radius: 5 mm, position: [80 mm, 0 mm, 30 mm]}",
                    "{depth_max: 1 mm, step: 0.5 mm}"));
  const auto r = run_cli("run '" + c.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "never touches the shell")) << r.output;
  EXPECT_TRUE(contains(r.output, "indenter")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "path.csv"));
}

TEST(RunCommand, IndenterStartingInsideTheShellIsRefused) {
  const fs::path dir = fresh_dir("run_inside");
  const fs::path c = write_case(
      dir, cap_case("linear", "{shape: sphere, radius: 12.7 mm, position: [0 mm, 0 mm, 5 mm]}",
                    "{depth_max: 1 mm, step: 0.5 mm}"));
  const auto r = run_cli("run '" + c.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "starts inside the shell")) << r.output;
}

TEST(RunCommand, NonPositiveRadiusAndUnknownShapeAreRefused) {
  const fs::path dir = fresh_dir("run_radius");
  for (const std::string indenter :
       {"{shape: sphere, radius: -2 mm}", "{shape: sphere, radius: 0 mm}", "{shape: cone}"}) {
    const fs::path c = write_case(dir, cap_case("linear", indenter, "{depth_max: 1 mm}"));
    const auto r = run_cli("run '" + c.string() + "'");
    EXPECT_EQ(r.exit_code, 2) << indenter << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "indenter.")) << r.output;
  }
}

TEST(RunCommand, ZeroDirectionIsRefused) {
  const fs::path dir = fresh_dir("run_direction");
  const fs::path c =
      write_case(dir, cap_case("linear", "{shape: sphere, radius: 12.7 mm, direction: [0, 0, 0]}",
                               "{depth_max: 1 mm}"));
  const auto r = run_cli("run '" + c.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "indenter.direction")) << r.output;
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// Issue 5 item 5: a pseudo-arclength run also reports the fixed depths 0, step, 2 step, ... by
// interpolation on the branch, each row marked; converged points on the grid are marked 0.
TEST(RunCommand, PseudoArclengthWritesTheInterpolatedDepthGrid) {
  const fs::path dir = fresh_dir("run_grid");
  const fs::path c = testing::write_case(
      dir,
      cap_case("nonlinear", "{shape: sphere, radius: 12.7 mm}",
               "{method: pseudo_arclength, depth_max: 0.5 mm, step: 0.1 mm, step_max: 0.3 mm}"));
  const auto r = run_cli("run '" + c.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir / "out" / "path_grid.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, path_csv_header() + ",interpolated");
  std::vector<double> depths;
  int interpolated = 0;
  while (std::getline(in, line)) {
    depths.push_back(std::stod(line.substr(0, line.find(','))));
    interpolated += line.back() == '1';
  }
  ASSERT_EQ(depths.size(), 6u);  // 0, 0.1, ..., 0.5
  for (std::size_t i = 0; i < depths.size(); ++i) EXPECT_NEAR(depths[i], 0.1 * i, 1e-12);
  EXPECT_GT(interpolated, 0);
  EXPECT_LT(interpolated, 6);  // the start and the end are converged points
}

}  // namespace
}  // namespace si

namespace si {
namespace {

TEST(RunCommand, ResumeWithoutCheckpointIsRefused) {
  const fs::path dir = fresh_dir("run_resume_missing");
  const fs::path c = testing::write_case(
      dir, cap_case("nonlinear", "{shape: sphere, radius: 12.7 mm}", "{depth_max: 0.2 mm}"));
  const auto r =
      run_cli("run '" + c.string() + "' --resume --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "--resume")) << r.output;
  EXPECT_TRUE(contains(r.output, "nothing to resume")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "path.csv"));
}

}  // namespace
}  // namespace si
