// End-to-end tests of `shellindent fit`: the table, the JSON (default path beside the CSV and
// --json), --range, polynomial degree selection and the interpolation warning, and the input
// errors (exit code 2) that name the file, line, column or option.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_test_support.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::fresh_dir;
using testing::run_cli;

// A force-depth path T = 350 h^1.37 from h = 0 (exact to the 12 digits written), with a text
// column that the fit never reads.
fs::path write_power_csv(const fs::path& dir) {
  const fs::path path = dir / "path.csv";
  std::ofstream f(path);
  f.precision(12);
  f << "# synthetic force-depth path\ndepth_mm,force_N,label\n";
  for (int i = 0; i <= 20; ++i) {
    const double h = 0.1 * i;
    f << h << "," << 350.0 * std::pow(h, 1.37) << ",step " << i << "\n";
  }
  return path;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

std::string q(const fs::path& p) {
  return "'" + p.string() + "'";
}

TEST(FitCommand, PowerLawTableAndDefaultJson) {
  const fs::path dir = fresh_dir("fit_power");
  const auto r =
      run_cli("fit " + q(write_power_csv(dir)) + " --model power --x depth_mm --y force_N");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* part : {"C1", "C2", "R^2", "RMSE", "95% CI", "21 points", "converged"})
    EXPECT_TRUE(contains(r.output, part)) << part << "\n" << r.output;
  const auto j = read_json(dir / "path.fit-power.json");
  EXPECT_EQ(j.at("status"), "converged");
  // The data carry 12 significant digits: the parameters come back to 1e-8 (issue 6).
  EXPECT_NEAR(j.at("parameters")[0].at("value").get<double>(), 350.0, 350.0 * 1e-8);
  EXPECT_NEAR(j.at("parameters")[1].at("value").get<double>(), 1.37, 1.37 * 1e-8);
  EXPECT_EQ(j.at("statistics").at("points"), 21);
  EXPECT_EQ(j.at("residuals").size(), 21u);
}

TEST(FitCommand, RangeAndJsonOption) {
  const fs::path dir = fresh_dir("fit_range");
  const auto r = run_cli("fit " + q(write_power_csv(dir)) +
                         " --model hertz --x depth_mm --y force_N --range 0.5:1.5 --json " +
                         q(dir / "out" / "h.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = read_json(dir / "out" / "h.json");
  EXPECT_EQ(j.at("statistics").at("points"), 11);  // h = 0.5, 0.6, ..., 1.5
  EXPECT_EQ(j.at("parameters")[0].at("name"), "C");
}

TEST(FitCommand, PowerLogLeavesOutTheOrigin) {
  const fs::path dir = fresh_dir("fit_powerlog");
  const auto r =
      run_cli("fit " + q(write_power_csv(dir)) + " --model power-log --x depth_mm --y force_N");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "1 point(s) with x <= 0")) << r.output;
  const auto j = read_json(dir / "path.fit-power-log.json");
  EXPECT_NEAR(j.at("parameters")[1].at("value").get<double>(), 1.37, 1e-8);
  EXPECT_EQ(j.at("excluded_points"), 1);
}

fs::path write_angle_csv(const fs::path& dir, int n) {
  const fs::path path = dir / "c1.csv";
  std::ofstream f(path);
  f << "angle_deg,C1\n";
  for (int i = 0; i < n; ++i) {
    const double a = 15.0 * i;
    f << a << "," << 2.0 - 0.03 * a + 4e-4 * a * a - 2e-6 * a * a * a + 0.01 * ((i % 3) - 1)
      << "\n";
  }
  return path;
}

// Issue 6: a 6th-degree polynomial through 7 points is flagged as interpolation.
TEST(FitCommand, SixthDegreeThroughSevenPointsWarnsOfInterpolation) {
  const fs::path dir = fresh_dir("fit_interp");
  const auto r = run_cli("fit " + q(write_angle_csv(dir, 7)) +
                         " --model poly --x angle_deg --y C1 --degree 6");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "WARNING: interpolation")) << r.output;
  EXPECT_TRUE(read_json(dir / "c1.fit-poly.json").at("interpolation").get<bool>());
}

TEST(FitCommand, AutoDegreeReportsEveryCandidate) {
  const fs::path dir = fresh_dir("fit_auto");
  const auto r = run_cli("fit " + q(write_angle_csv(dir, 13)) +
                         " --model poly --x angle_deg --y C1 --degree auto --criterion aic");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "degree selection by AIC")) << r.output;
  const auto j = read_json(dir / "c1.fit-poly.json");
  EXPECT_EQ(j.at("degree_selection").at("scores").size(), 11u);  // degrees 0..10 for 13 points
  EXPECT_EQ(j.at("parameters").size(), j.at("degree_selection").at("chosen").get<size_t>() + 1);
}

TEST(FitCommand, InputErrorsExitTwoAndSayWhere) {
  const fs::path dir = fresh_dir("fit_errors");
  const std::string csv = q(write_power_csv(dir));
  struct Case {
    std::string args;
    std::vector<std::string> parts;
  };
  const Case cases[] = {
      {"--model power --x depth --y force_N", {"no such column", "depth_mm", "did you mean"}},
      {"--model powr --x depth_mm --y force_N", {"unknown model", "did you mean 'power'"}},
      {"--model power --x depth_mm --y label", {"path.csv:3", "label", "not a number", "column 3"}},
      {"--model power --x depth_mm --y force_N --range 5:9", {"no points", "[0, 2]"}},
      {"--model power --x depth_mm --y force_N --range 1-2", {"--range", "a:b"}},
      {"--model power --x depth_mm --y force_N --degree 2", {"--degree", "poly only"}},
      {"--model poly --x depth_mm --y force_N --degree 30", {"needs at least 31 points"}},
  };
  for (const auto& c : cases) {
    const auto r = run_cli("fit " + csv + " " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    for (const auto& part : c.parts)
      EXPECT_TRUE(contains(r.output, part)) << c.args << ": " << part << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "path.fit-power.json"));  // nothing written on bad input
}

}  // namespace
}  // namespace si
