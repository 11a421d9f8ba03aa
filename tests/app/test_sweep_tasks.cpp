// `shellindent sweep --emit DIR` and `--collect DIR` (app/sweep_tasks.hpp): the cases emitted
// with a task list, the tasks run by hand one after another (as a SLURM array or GNU parallel
// would run them), and the collected table byte for byte the one `shellindent sweep -j 2`
// writes; unfinished cases reported as not run or failed with the reason; bad input refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "io/csv_table.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using namespace testing;  // run_cli, fresh_dir, read_file, contains (cli_test_support.hpp)

// Two indenter radii on the paper's cap, coarse and short in the quick mode (about 1 s a case).
fs::path two_radii_study(const fs::path& dir, const std::string& name = "radii.yaml") {
  const fs::path p = dir / name;
  std::ofstream(p) << "base: " << SHELLINDENT_SOURCE_DIR << "/studies/paper_cap.yaml\n"
                   << "vary: {indenter.radius: [8 mm, 12.7 mm]}\n"
                      "fit: {model: power}\n"
                      "quick: {mesh.size_apex: 3 mm, mesh.size_edge: 5 mm, path.depth_max: 0.5 mm,"
                      " output.vtu_every: 0}\n";
  return p;
}

std::vector<std::string> lines_of(const fs::path& file) {
  std::istringstream in(read_file(file));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

// The status column of DIR/sweep.csv.
std::vector<std::string> statuses(const fs::path& dir) {
  const CsvTable t = read_csv_table((dir / "sweep.csv").string());
  std::vector<std::string> s;
  for (const auto& row : t.rows) s.push_back(row[t.column_index("status")]);
  return s;
}

TEST(SweepTasks, EmittedTasksRunByHandAndCollectedGiveTheSweepsTable) {
  const fs::path dir = fresh_dir("sweep_tasks");
  const fs::path study = two_radii_study(dir);
  const fs::path reference = dir / "reference", emitted = dir / "emitted";
  const auto sweep = run_cli("sweep " + quoted(study) + " --quick -j 2 --out " + quoted(reference));
  ASSERT_EQ(sweep.exit_code, 0) << sweep.output;

  const auto emit = run_cli("sweep " + quoted(study) + " --quick --emit " + quoted(emitted));
  ASSERT_EQ(emit.exit_code, 0) << emit.output;
  EXPECT_TRUE(contains(emit.output, "SLURM_ARRAY_TASK_ID")) << emit.output;
  EXPECT_TRUE(contains(read_file(emitted / "README.txt"), "parallel -j 8 <"));
  EXPECT_TRUE(contains(read_file(emitted / "README.txt"), "--array=1-2"));
  const std::vector<std::string> tasks = lines_of(emitted / "tasks.txt");
  ASSERT_EQ(tasks.size(), 2u);
  EXPECT_TRUE(contains(
      tasks[0], " run '" + (emitted / "cases" / "001_8_mm" / "case.yaml").string() + "' --out '" +
                    (emitted / "cases" / "001_8_mm").string() + "' --threads 1"))
      << tasks[0];
  EXPECT_FALSE(fs::exists(emitted / "cases" / "001_8_mm" / "path.json"));  // nothing ran

  // Nothing run yet: both cases not run, exit 1, the table written.
  auto collect = run_cli("sweep --collect " + quoted(emitted));
  EXPECT_EQ(collect.exit_code, 1) << collect.output;
  EXPECT_EQ(statuses(emitted), (std::vector<std::string>{"not_run", "not_run"}));
  EXPECT_TRUE(contains(read_file(emitted / "sweep.csv"), "its task has not run"));

  // The first task (line 1: SLURM array task 1), then the collection: one finished, one not run.
  ASSERT_EQ(std::system(("sed -n 1p " + quoted(emitted / "tasks.txt") + " | bash").c_str()), 0);
  collect = run_cli("sweep --collect " + quoted(emitted));
  EXPECT_EQ(collect.exit_code, 1) << collect.output;
  EXPECT_EQ(statuses(emitted)[1], "not_run");
  EXPECT_NE(statuses(emitted)[0], "not_run");

  // Emitting again lists only the case not done; running it completes the sweep.
  ASSERT_EQ(run_cli("sweep " + quoted(study) + " --quick --emit " + quoted(emitted)).exit_code, 0);
  ASSERT_EQ(lines_of(emitted / "tasks.txt").size(), 1u);
  ASSERT_EQ(std::system(("bash " + quoted(emitted / "tasks.txt")).c_str()), 0);
  collect = run_cli("sweep " + quoted(study) + " --collect " + quoted(emitted));
  ASSERT_EQ(collect.exit_code, 0) << collect.output;
  EXPECT_EQ(read_file(emitted / "sweep.csv"), read_file(reference / "sweep.csv"));
  EXPECT_EQ(read_file(emitted / "sweep.json"), read_file(reference / "sweep.json"));

  // A case whose run wrote no path.json: failed, with its log's last line as the reason.
  fs::remove(emitted / "cases" / "002_12.7_mm" / "path.json");
  std::ofstream(emitted / "cases" / "002_12.7_mm" / "run.log")
      << "shellindent: error: out of disk\n";
  collect = run_cli("sweep --collect " + quoted(emitted));
  EXPECT_EQ(collect.exit_code, 1) << collect.output;
  EXPECT_EQ(statuses(emitted)[1], "failed");
  EXPECT_TRUE(contains(read_file(emitted / "sweep.csv"), "shellindent: error: out of disk"));
}

TEST(SweepTasks, BadEmitAndCollectAreRefusedWithExitTwo) {
  const fs::path dir = fresh_dir("sweep_tasks_bad");
  const fs::path study = two_radii_study(dir), other = two_radii_study(dir, "other.yaml");
  const fs::path emitted = dir / "emitted";
  ASSERT_EQ(run_cli("sweep " + quoted(study) + " --quick --emit " + quoted(emitted)).exit_code, 0);

  auto r = run_cli("sweep " + quoted(other) + " --quick --emit " + quoted(emitted));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "--emit = '" + emitted.string() +
                                     "': the directory holds the emitted sweep of another study"))
      << r.output;

  const fs::path stranger = dir / "stranger";
  fs::create_directories(stranger);
  std::ofstream(stranger / "notes.txt") << "mine\n";
  r = run_cli("sweep " + quoted(study) + " --emit " + quoted(stranger));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "the directory is not empty and holds no emitted sweep"))
      << r.output;
  EXPECT_FALSE(fs::exists(stranger / "tasks.txt"));

  r = run_cli("sweep --collect " + quoted(stranger));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "--collect = '" + stranger.string() +
                                     "': no emitted sweep here (sweep_tasks.json is missing)"))
      << r.output;
  EXPECT_FALSE(fs::exists(stranger / "sweep.csv"));

  r = run_cli("sweep " + quoted(other) + " --collect " + quoted(emitted));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "not of this study")) << r.output;

  r = run_cli("sweep --collect " + quoted(emitted) + " --emit " + quoted(dir / "x"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "exclude each other")) << r.output;
  EXPECT_FALSE(fs::exists(emitted / "sweep.csv"));
}

}  // namespace
}  // namespace si
