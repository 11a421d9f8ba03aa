// End-to-end tests of `shellindent sweep`: the paper's lay-up study in its quick mode, resuming a
// sweep whose case lost its results (only that case runs again; the table equals a sequential
// run's), rerunning the cases whose results another build wrote, and bad input refused before
// anything runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "io/csv_table.hpp"
#include "io/source_fingerprint.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::fresh_dir;
using testing::read_file;
using testing::run_cli;

const std::string kStudies = std::string(SHELLINDENT_SOURCE_DIR) + "/studies";

// Occurrences of `part` in `text`.
int count(const std::string& text, const std::string& part) {
  int n = 0;
  for (auto p = text.find(part); p != std::string::npos; p = text.find(part, p + 1)) ++n;
  return n;
}

// A two-case study of the paper's cap, small enough for a unit test in its quick mode.
fs::path two_case_study(const fs::path& dir) {
  const fs::path p = dir / "two.yaml";
  std::ofstream(p) << "base: " << kStudies << "/paper_cap.yaml\n"
                   << "vary: {laminate.layup: [\"[0/0]2S\", \"[0/90]2S\"]}\n"
                      "quick: {mesh.size_apex: 3 mm, mesh.size_edge: 5 mm, path.depth_max: 0.5 mm,"
                      " output.vtu_every: 0}\n";
  return p;
}

TEST(SweepCommand, PaperLayupsQuickRunsAllEightCasesAndFitsTheContactLaw) {
  const fs::path dir = fresh_dir("sweep_paper_quick");
  const auto r = run_cli("sweep '" + kStudies + "/paper_layups.yaml' --quick -j 2 --out '" +
                         dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable t = read_csv_table((dir / "sweep.csv").string());
  ASSERT_EQ(t.rows.size(), 8u);
  const int status = t.column_index("status");
  for (const auto& row : t.rows)  // a pseudo-arclength path that reaches depth_max: reached_bound
    EXPECT_TRUE(row[status] == "completed" || row[status] == "reached_bound") << row[status];
  for (double c1 : t.numeric_column("C1")) EXPECT_GT(c1, 0.0);
  EXPECT_TRUE(fs::exists(dir / "sweep.json"));
  EXPECT_TRUE(fs::exists(dir / "cases" / "002_15_-15_2S" / "path.csv"));
  EXPECT_TRUE(contains(r.output, "8/8")) << r.output;

  // The sweep fits the force on the depth grid, read from path_grid.csv (the Hermite-interpolated
  // table of the adaptive path): the same C1, C2 as `shellindent fit` on that file.
  const fs::path c2 = dir / "cases" / "002_15_-15_2S";
  const fs::path fit_json = dir / "grid_fit.json";
  const auto f =
      run_cli("fit '" + (c2 / "path_grid.csv").string() +
              "' --model power --x depth_mm --y force_N --json '" + fit_json.string() + "'");
  ASSERT_EQ(f.exit_code, 0) << f.output;
  const nlohmann::json fit = nlohmann::json::parse(read_file(fit_json));
  const std::vector<double> C1 = t.numeric_column("C1"), C2 = t.numeric_column("C2");
  EXPECT_NEAR(C1[1], fit["parameters"][0]["value"].get<double>(), 1e-6 * C1[1]);
  EXPECT_NEAR(C2[1], fit["parameters"][1]["value"].get<double>(), 1e-6 * C2[1]);
}

TEST(SweepCommand, RerunSkipsFinishedCasesAndMatchesASequentialRun) {
  const fs::path dir = fresh_dir("sweep_resume");
  const fs::path study = two_case_study(dir);
  const std::string parallel = (dir / "parallel").string();
  const std::string sequential = (dir / "sequential").string();
  const std::string args = "sweep '" + study.string() + "' --quick ";
  ASSERT_EQ(run_cli(args + "-j 2 --out '" + parallel + "'").exit_code, 0);
  fs::remove(fs::path(parallel) / "cases" / "002_0_90_2S" / "path.json");
  const auto again = run_cli(args + "-j 2 --out '" + parallel + "'");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(count(again.output, "already done, skipped"), 1) << again.output;
  EXPECT_TRUE(contains(again.output, "case 1 (laminate.layup = [0/0]2S): already done"))
      << again.output;
  EXPECT_TRUE(contains(again.output, "case 2 (laminate.layup = [0/90]2S): reached_bound"))
      << again.output;
  ASSERT_EQ(run_cli(args + "-j 1 --out '" + sequential + "'").exit_code, 0);
  EXPECT_EQ(read_file(fs::path(parallel) / "sweep.csv"),
            read_file(fs::path(sequential) / "sweep.csv"));
}

// Rewrites the build record of a case's path.json: as if another build (or, with `erase`, one
// from before the record existed) had written its results.
void rewrite_build_record(const fs::path& path_json, bool erase) {
  nlohmann::json j = nlohmann::json::parse(read_file(path_json));
  if (erase)
    j.erase("build");
  else
    j["build"]["source_fingerprint"] = std::string(64, '0');
  std::ofstream(path_json) << j.dump(1);
}

TEST(SweepCommand, RerunRunsAgainTheCasesAnotherBuildWrote) {
  const fs::path dir = fresh_dir("sweep_stale");
  const fs::path study = two_case_study(dir);
  const fs::path out = dir / "out";
  const std::string args =
      "sweep '" + study.string() + "' --quick -j 2 --out '" + out.string() + "'";
  ASSERT_EQ(run_cli(args).exit_code, 0);
  const fs::path first = out / "cases" / "001_0_0_2S" / "path.json";
  const fs::path second = out / "cases" / "002_0_90_2S" / "path.json";
  // The record names this build: the same fingerprint as the library the tests link.
  const nlohmann::json j = nlohmann::json::parse(read_file(first));
  EXPECT_EQ(j["build"]["source_fingerprint"].get<std::string>(), source_fingerprint());
  EXPECT_EQ(j["build"]["source_fingerprint"].get<std::string>().size(), 64u);
  const std::string csv = read_file(out / "sweep.csv");

  rewrite_build_record(first, false);
  rewrite_build_record(second, true);
  const auto again = run_cli(args);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(count(again.output, "written by another build"), 2) << again.output;
  EXPECT_EQ(count(again.output, "already done, skipped"), 0) << again.output;
  for (const fs::path& p : {first, second})  // rerun: the record is this build's again
    EXPECT_EQ(nlohmann::json::parse(read_file(p))["build"]["source_fingerprint"],
              source_fingerprint());
  EXPECT_EQ(read_file(out / "sweep.csv"), csv);  // same code, same table

  // What must not be reported: a third run finds both done by this build and reruns nothing.
  const auto third = run_cli(args);
  EXPECT_EQ(count(third.output, "already done, skipped"), 2) << third.output;
  EXPECT_EQ(count(third.output, "another build"), 0) << third.output;

  // --emit, given the finished cases with one of them stale, lists that one as a task, and only it.
  const fs::path emitted = dir / "emitted";
  const std::string emit =
      "sweep '" + study.string() + "' --quick --emit '" + emitted.string() + "'";
  ASSERT_EQ(run_cli(emit).exit_code, 0);
  fs::copy(out / "cases", emitted / "cases",
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  rewrite_build_record(emitted / "cases" / "001_0_0_2S" / "path.json", false);
  const auto again_emitted = run_cli(emit);
  ASSERT_EQ(again_emitted.exit_code, 0) << again_emitted.output;
  EXPECT_EQ(count(again_emitted.output, "written by another build"), 1) << again_emitted.output;
  const std::string tasks = read_file(emitted / "tasks.txt");
  EXPECT_EQ(count(tasks, "\n"), 1) << tasks;
  EXPECT_TRUE(contains(tasks, "001_0_0_2S")) << tasks;
}

TEST(SweepCommand, UnknownKeyIsRefusedBeforeAnythingRuns) {
  const fs::path dir = fresh_dir("sweep_bad_key");
  const fs::path study = dir / "bad.yaml";
  std::ofstream(study) << "base: " << kStudies << "/paper_cap.yaml\n"
                       << "vary: {mesh.size_apexx: [1 mm, 2 mm]}\n";
  const auto r = run_cli("sweep '" + study.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "bad.yaml case 1")) << r.output;
  EXPECT_TRUE(contains(r.output, "mesh.size_apexx")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "cases"));
}

}  // namespace
}  // namespace si
