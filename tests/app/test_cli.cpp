// End-to-end tests of the `shellindent` executable: exit codes (0 ok, 2 bad input), messages
// naming the option and value, --help, and that failed runs write no result files.
#include <gtest/gtest.h>

#include "cli_test_support.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using si::testing::contains;
using si::testing::fresh_dir;
using si::testing::run_cli;

TEST(Cli, HelpExplainsTheCommands) {
  const auto r = run_cli("--help");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* word : {"section", "materials", "layup", "units"})
    EXPECT_TRUE(contains(r.output, word)) << word << "\n" << r.output;
  const auto s = run_cli("section --help");
  EXPECT_EQ(s.exit_code, 0);
  EXPECT_TRUE(contains(s.output, "--ply-thickness")) << s.output;
  EXPECT_TRUE(contains(s.output, "Examples")) << s.output;
}

TEST(Cli, SectionFromOptionsPrintsMatricesWithUnits) {
  const auto r =
      run_cli("section --layup '[45/-45]2S' --material paper-carbon-epoxy --ply-thickness 0.475mm");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* part : {"A (N/mm)", "B (N)", "D (N*mm)", "G (N/mm)", "F-bar top", "c_L"})
    EXPECT_TRUE(contains(r.output, part)) << part << "\n" << r.output;
}

TEST(Cli, SectionJsonIsCompleteAndSymmetric) {
  const fs::path dir = fresh_dir("json");
  const fs::path json = dir / "s.json";
  const auto r = run_cli("section --layup '[0/90]2S' --ply-thickness '0.475 mm' --json '" +
                         json.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  const auto& a = j.at("vam").at("A_R");
  ASSERT_EQ(a.size(), 6u);
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(a[i][k].get<double>(), a[k][i].get<double>());
  EXPECT_EQ(j.at("plies_bottom_to_top").size(), 8u);
  EXPECT_NEAR(j.at("thickness_mm").get<double>(), 3.8, 1e-12);
}

TEST(Cli, BadOptionValuesExitTwoNamingOptionAndValue) {
  struct Case {
    const char* args;
    const char* expected;
  };
  const Case cases[] = {
      {"section --layup '[45/-45' --ply-thickness 0.475mm", "--layup = '[45/-45'"},
      {"section --layup '[0/90]S' --ply-thickness 0.475", "--ply-thickness = '0.475'"},
      {"section --layup '[0/90]S' --ply-thickness '0.475 GPa'", "wrong unit"},
      {"section --layup '[0/90]S' --ply-thickness '-0.475 mm'", "--ply-thickness"},
      {"section --layup '[0/90]S' --ply-thickness 1mm --material unobtainium", "unobtainium"},
      {"section --layup '[0/90]S' --ply-thickness 1mm --reference sideways", "--reference"},
      {"section --layup '[0/90]S'", "--ply-thickness"},
      {"section --no-such-option", "no-such-option"},
      {"section /no/such/case.yaml", "/no/such/case.yaml"},
      {"section --layup '[0]' --ply-thickness 1mm --vam-order 1", "--vam-order"},
      {"layup '[0//90]'", "[0//90]"},
      {"frobnicate", "frobnicate"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, c.expected)) << c.args << "\n" << r.output;
  }
}

TEST(Cli, FailedRunWritesNoResultFile) {
  const fs::path dir = fresh_dir("nohalf");
  const fs::path json = dir / "s.json";
  const auto r =
      run_cli("section --layup '[0/90]S' --ply-thickness 0.475 --json '" + json.string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(fs::exists(json));
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Cli, PaperSweepWritesTableCsvAndJson) {
  const fs::path dir = fresh_dir("paper");
  const auto r = run_cli("section --paper --out '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "[45/-45]2S"));
  std::ifstream csv(dir / "paper_sections.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 1 + 8);  // header, theta = 0..90 by 15, [0/90]2S
  std::ifstream json(dir / "paper_sections.json");
  EXPECT_EQ(nlohmann::json::parse(json).size(), 8u);
}

// `-o DIR` is what users type first (it was refused: "The following arguments were not expected").
TEST(Cli, EveryCommandWithAnOutputDirectoryTakesTheShortFlag) {
  for (const char* command : {"section", "static", "run", "sweep", "calibrate"}) {
    const auto r = run_cli(std::string(command) + " --help");
    EXPECT_TRUE(contains(r.output, "-o,--out")) << command << "\n" << r.output;
  }
  const fs::path dir = fresh_dir("paper_short_flag");
  const auto r = run_cli("section --paper -o '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "paper_sections.csv"));
}

// A misspelt option is named with the closest one, before its value can be taken for the case
// file (CLI11 alone said "case: File does not exist: 2" for `run --treads 2`); known options,
// `--name=value` and values after `--` pass.
TEST(Cli, UnknownOptionIsNamedWithTheClosestOne) {
  for (const char* args : {"run --treads 2", "run --treads=2"}) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "'--treads': unknown option of 'run'")) << r.output;
    EXPECT_TRUE(contains(r.output, "did you mean '--threads'?")) << r.output;
    EXPECT_FALSE(contains(r.output, "File does not exist")) << r.output;
  }
  const fs::path dir = fresh_dir("paper_long_flag");
  const auto ok = run_cli("section --paper --out='" + dir.string() + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  const auto far = run_cli("sweep --frobnicate");
  EXPECT_EQ(far.exit_code, 2) << far.output;
  EXPECT_TRUE(contains(far.output, "unknown option of 'sweep'; its options: --help")) << far.output;
}

TEST(Cli, LayupCommandExpandsNotation) {
  const auto r = run_cli("layup '[0/+-45/90]s'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "8 plies")) << r.output;
}

TEST(Cli, MaterialsListsThePaperMaterial) {
  const auto r = run_cli("materials");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_TRUE(contains(r.output, "paper-carbon-epoxy")) << r.output;
  // The prepregs with their strengths and toughness (docs/materials.md).
  EXPECT_TRUE(contains(r.output, "im7-8552")) << r.output;
  EXPECT_TRUE(contains(r.output, "X_T 2326.2")) << r.output;
  EXPECT_TRUE(contains(r.output, "G_IIc 0.788")) << r.output;
}

}  // namespace
