// Interrupted and resumed runs of `shellindent run` (issue 13 items 10-14, 16-18, 21): SIGTERM
// handled like Ctrl-C, a resume that refuses another case, a kill at any instant that leaves a
// resumable state (or a clear "nothing to resume"), resumed results byte-identical to an
// uninterrupted run's, path.pvd listing every frame, the last point's VTU, output.formats.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_support.hpp"
#include "test_paths.hpp"

extern char** environ;

namespace si {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::fresh_dir;
using testing::read_file;
using testing::run_cli;

// A coarse quarter of the paper's cap, nonlinear, 0.6 mm by pseudo-arclength in small steps:
// about twenty points, a fraction of a second per run on one thread.
std::string small_case(const std::string& layup = "[0/0]2S", const std::string& output = "") {
  return "material: paper-carbon-epoxy\n"
         "laminate: {layup: \"" +
         layup +
         "\", ply_thickness: 0.475 mm}\n"
         "mesh: {size_apex: 1.5 mm, size_edge: 4 mm, refine_radius: 8 mm, symmetry: quarter}\n"
         "path: {method: pseudo_arclength, depth_max: 0.6 mm, step: 0.03 mm, step_max: 0.03 mm}\n"
         "output: {vtu_every: 3" +
         output + "}\n";
}

struct Spawned {
  pid_t pid = -1;
};

// `shellindent ARGS...` in the background, its output to `log`.
Spawned spawn(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all{SHELLINDENT_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  Spawned s;
  posix_spawn(&s.pid, SHELLINDENT_EXE, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return s;
}

// Exit code, or -signal if killed.
int wait_for(const Spawned& s) {
  int status = 0;
  waitpid(s.pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

std::string run_args(const fs::path& c, const fs::path& out) {
  return "run '" + c.string() + "' --threads 1 --out '" + out.string() + "'";
}

// The frames path.pvd lists, in order.
std::vector<std::string> pvd_frames(const fs::path& pvd) {
  const std::string text = read_file(pvd);
  std::vector<std::string> frames;
  const std::regex file("file=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), file); it != std::sregex_iterator();
       ++it)
    frames.push_back((*it)[1]);
  return frames;
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// The uninterrupted run of small_case(), once per test process. ctest runs each test in its own
// process, several at a time: the directory carries the process id so that two tests of this
// file never share (and delete) one reference run.
const fs::path& reference_run() {
  static const fs::path out = [] {
    const fs::path dir = fresh_dir("interrupt_reference_" + std::to_string(getpid()));
    const fs::path c = testing::write_case(dir, small_case());
    const auto r = run_cli(run_args(c, dir / "out"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return dir / "out";
  }();
  return out;
}

// Waits until `file` exists (the run is under way), at most `seconds`.
bool wait_for_file(const fs::path& file, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!fs::exists(file))
    if (std::chrono::steady_clock::now() > end)
      return false;
    else
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
  return true;
}

// A background `run` of small_case() in the fresh directory `name`, under way once its VTU
// `frame` exists (`started` false, with the log, if it never did within a minute).
struct BackgroundRun {
  fs::path dir, case_file, out, log;
  Spawned process;
  bool started = false;
};

BackgroundRun start_run(const std::string& name, const char* frame, const char* log = "run.log") {
  BackgroundRun r;
  r.dir = fresh_dir(name);
  r.case_file = testing::write_case(r.dir, small_case());
  r.out = r.dir / "out";
  r.log = r.dir / log;
  r.process =
      spawn({"run", r.case_file.string(), "--threads", "1", "--out", r.out.string()}, r.log);
  r.started = wait_for_file(r.out / frame, 60);
  return r;
}

// `shellindent static` stopped by SIGTERM mid-path keeps every converged step (static.csv and
// static.json written), says where and why, exits 1 and leaves no lock behind. The case is
// Sze 3.2 in 4000 load steps (about a minute uninterrupted).
TEST(RunInterrupts, StaticRunStoppedBySigtermKeepsItsStepsAndSaysWhy) {
  const fs::path dir = fresh_dir("static_sigterm");
  std::string text = testing::read_file(fs::path(SHELLINDENT_SOURCE_DIR) / "studies" / "sze" /
                                        "sze_3-2_cantilever_end_moment.yaml");
  text.replace(text.find("steps: 20"), 9, "steps: 4000");
  const fs::path c = testing::write_case(dir, text);
  const fs::path log = dir / "static.log";
  const Spawned p = spawn({"static", c.string(), "--out", (dir / "out").string()}, log);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (testing::read_file(log).find("step 20:") == std::string::npos &&
         std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(p.pid, SIGTERM);
  EXPECT_EQ(wait_for(p), 1);
  const std::string said = testing::read_file(log);
  EXPECT_TRUE(contains(said, "the run stopped after")) << said;
  EXPECT_TRUE(contains(said, "interrupted (SIGTERM)")) << said;
  const std::string csv = testing::read_file(dir / "out" / "static.csv");
  EXPECT_GE(std::count(csv.begin(), csv.end(), '\n'), 21) << "header + at least 20 steps";
  EXPECT_TRUE(fs::exists(dir / "out" / "static.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / ".shellindent.lock"));
}

// Items 17 and 21: the last point has its VTU although vtu_every does not divide its index,
// and a run that reached depth_max says so in the path's terms.
TEST(RunInterrupts, UninterruptedRunWritesTheLastFrameAndSaysItReachedDepthMax) {
  const fs::path& out = reference_run();
  const nlohmann::json path = nlohmann::json::parse(read_file(out / "path.json"));
  const std::size_t points = path.at("points").size();
  ASSERT_GT(points, 6u);
  EXPECT_EQ(path.at("reason").get<std::string>(), "reached depth_max 0.6 mm");
  const std::vector<std::string> frames = pvd_frames(out / "path.pvd");
  char last[32];
  std::snprintf(last, sizeof last, "path_%04zu.vtu", points - 1);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.back(), last);
  EXPECT_TRUE(fs::exists(out / last));
  for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "path_%04zu.vtu", 3 * i);
    EXPECT_EQ(frames[i], name);
  }
}

// Items 11, 13 and 16: SIGTERM stops the run after the current point with every converged point
// written and exit 1, like Ctrl-C; the resumed run gives files byte-identical to the
// uninterrupted run's, and path.pvd lists the frames from before and after the stop.
TEST(RunInterrupts, SigtermWritesEveryPointAndTheResumeIsBitIdentical) {
  const fs::path& reference = reference_run();
  const BackgroundRun run = start_run("interrupt_sigterm", "path_0003.vtu");
  ASSERT_TRUE(run.started) << read_file(run.log);
  const fs::path& out = run.out;
  kill(run.process.pid, SIGTERM);
  const int code = wait_for(run.process);
  const std::string log = read_file(run.log);
  if (code == 0) GTEST_SKIP() << "the run ended before the signal arrived:\n" << log;
  EXPECT_EQ(code, 1) << log;
  EXPECT_TRUE(contains(log, "interrupted (SIGTERM)")) << log;
  const nlohmann::json stopped = nlohmann::json::parse(read_file(out / "path.json"));
  EXPECT_GE(stopped.at("points").size(), 4u);  // every converged point, path_0003.vtu's included
  EXPECT_TRUE(fs::exists(out / "path.csv"));
  EXPECT_TRUE(fs::exists(out / "events.json"));
  EXPECT_EQ(stopped.at("reason"), "interrupted (SIGTERM)");  // not "stopped by the callback"
  // The stop says where a resume goes on: before point 10, from the start's checkpoint (a
  // stopped run keeps its last periodic one).
  const std::size_t n = stopped.at("points").size();
  EXPECT_TRUE(contains(log, "--resume continues from depth")) << log;
  if (n < 10) {
    EXPECT_TRUE(contains(log, "from depth 0 mm, point 1 of " + std::to_string(n))) << log;
  }

  const auto resumed = run_cli(run_args(run.case_file, out) + " --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  for (const char* file : {"path.csv", "path_grid.csv", "path.pvd"})
    EXPECT_EQ(read_file(out / file), read_file(reference / file)) << file << " differs";
  EXPECT_EQ(pvd_frames(out / "path.pvd"), pvd_frames(reference / "path.pvd"));
  for (const std::string& frame : pvd_frames(out / "path.pvd"))
    EXPECT_TRUE(fs::exists(out / frame)) << frame;
}

// Item 10: a checkpoint resumed with another case is refused, naming the key that differs, its
// line and both values; nothing is written.
TEST(RunInterrupts, ResumeWithAnotherCaseIsRefusedNamingWhatDiffers) {
  const fs::path dir = fresh_dir("interrupt_other_case");
  const fs::path c = testing::write_case(dir, small_case("[0/90]2S"));
  const fs::path out = dir / "out";
  ASSERT_EQ(run_cli(run_args(c, out)).exit_code, 0);
  const std::string before = read_file(out / "path.csv");
  const std::set<std::string> files = files_in(out);
  testing::write_case(dir, small_case("[0/0]2S", ", dir: elsewhere/"));  // output keys may change
  const auto r = run_cli(run_args(c, out) + " --resume");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  for (const char* part : {"case.yaml:2", "laminate.layup", "'[0/0]2S' here", "'[0/90]2S' in the"})
    EXPECT_TRUE(contains(r.output, part)) << part << "\n" << r.output;
  EXPECT_EQ(read_file(out / "path.csv"), before);
  EXPECT_EQ(files_in(out), files);

  testing::write_case(dir, small_case("[0/90]2S", ", dir: elsewhere/"));  // the same case again
  const auto same = run_cli(run_args(c, out) + " --resume");
  EXPECT_EQ(same.exit_code, 0) << same.output;
  EXPECT_EQ(read_file(out / "path.csv"), before);
}

// Item 18: output.formats is honoured (checkpoint.json is kept in any case, for --resume).
TEST(RunInterrupts, OutputFormatsAreHonoured) {
  const fs::path dir = fresh_dir("interrupt_formats");
  const fs::path c = testing::write_case(dir, small_case("[0/0]2S", ", formats: [csv]"));
  const auto r = run_cli(run_args(c, dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(files_in(dir / "out"),
            (std::set<std::string>{"path.csv", "path_grid.csv", "checkpoint.json"}));
  const fs::path c2 = testing::write_case(dir, small_case("[0/0]2S", ", formats: [json]"));
  ASSERT_EQ(run_cli(run_args(c2, dir / "out2")).exit_code, 0);
  EXPECT_EQ(files_in(dir / "out2"),
            (std::set<std::string>{"path.json", "events.json", "checkpoint.json"}));
}

// Item 12: a run killed (SIGKILL) at random instants leaves either a checkpoint from which
// --resume finishes with files byte-identical to the uninterrupted run's, or no checkpoint and
// a clear "nothing to resume" (exit 2); temporary files of the killed run are removed by the
// next one. The instants are spread over the whole run, write bursts included.
TEST(RunInterrupts, KillAtAnyInstantLeavesAResumableStateOrNothingToResume) {
  const fs::path& reference = reference_run();
  const fs::path dir = fresh_dir("interrupt_kill");
  const fs::path c = testing::write_case(dir, small_case());
  // The uninterrupted run's duration on this machine, to spread the kills over it.
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_cli(run_args(c, dir / "timing")).exit_code, 0);
  const double duration =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> instant(0.0, 1.05 * duration);
  int resumed = 0, nothing = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const fs::path out = dir / ("out" + std::to_string(trial));
    const Spawned run =
        spawn({"run", c.string(), "--threads", "1", "--out", out.string()}, dir / "run.log");
    std::this_thread::sleep_for(std::chrono::duration<double>(instant(rng)));
    kill(run.pid, SIGKILL);
    wait_for(run);
    const auto r = run_cli(run_args(c, out) + " --resume");
    if (r.exit_code == 2) {
      EXPECT_TRUE(contains(r.output, "nothing to resume")) << r.output;
      EXPECT_FALSE(fs::exists(out / "checkpoint.json"));
      ++nothing;
      continue;
    }
    ASSERT_EQ(r.exit_code, 0) << "trial " << trial << ":\n" << r.output;
    ++resumed;
    for (const char* file : {"path.csv", "path_grid.csv", "path.pvd"})
      EXPECT_EQ(read_file(out / file), read_file(reference / file)) << trial << ": " << file;
    for (const std::string& name : files_in(out))
      EXPECT_FALSE(name.size() > 4 && name.substr(name.size() - 4) == ".tmp") << name;
  }
  EXPECT_GT(resumed, 0);  // most instants fall after the first checkpoint
  std::cerr << "kills: " << resumed << " resumed, " << nothing << " nothing to resume, run "
            << duration << " s\n";
}

// Item 14: a second run into a directory that a running one is writing is refused at once.
TEST(RunInterrupts, SecondRunIntoTheSameDirectoryIsRefused) {
  const BackgroundRun first = start_run("interrupt_lock", "path_0000.vtu", "first.log");
  ASSERT_TRUE(first.started) << read_file(first.log);
  const fs::path& out = first.out;
  const auto second = run_cli(run_args(first.case_file, out));
  const int first_code = wait_for(first.process);
  EXPECT_EQ(first_code, 0) << read_file(first.log);
  if (!contains(second.output, "another shellindent run") && second.exit_code == 0)
    GTEST_SKIP() << "the first run ended before the second started";
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_TRUE(contains(second.output, "--out")) << second.output;
  EXPECT_EQ(read_file(out / "path.csv"), read_file(reference_run() / "path.csv"));
}

// Item 11 for a sweep: SIGTERM (or Ctrl-C) to `shellindent sweep` starts no more cases, passes
// the signal on to the running case, which stops after its point and writes what converged, and
// the sweep then writes its summary, the cases it did not start marked not_run, and exits 1. A
// rerun finishes the study.
TEST(RunInterrupts, SigtermToASweepStopsItsCasesAndSummarisesWhatRan) {
  const fs::path dir = fresh_dir("interrupt_sweep");
  const fs::path base = testing::write_case(dir, small_case());
  const fs::path study = dir / "study.yaml";
  std::ofstream(study) << "base: " << base.string() << "\n"
                       << "vary: {laminate.layup: [\"[0/0]2S\", \"[0/90]2S\", \"[90/0]2S\"]}\n";
  const fs::path out = dir / "out";
  const Spawned sweep =
      spawn({"sweep", study.string(), "-j", "1", "--out", out.string()}, dir / "sweep.log");
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  fs::path first_case;
  while (first_case.empty() && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out / "cases", ec))
      if (fs::exists(e.path() / "path_0003.vtu")) first_case = e.path();
  }
  ASSERT_FALSE(first_case.empty()) << read_file(dir / "sweep.log");
  kill(sweep.pid, SIGTERM);
  const int code = wait_for(sweep);
  const std::string log = read_file(dir / "sweep.log");
  EXPECT_EQ(code, 1) << log;
  EXPECT_TRUE(contains(log, "interrupted (SIGTERM)")) << log;
  // The running case stopped after its point with everything that converged written (or had
  // just finished); the sweep waited for it.
  const nlohmann::json path = nlohmann::json::parse(read_file(first_case / "path.json"));
  EXPECT_GE(path.at("points").size(), 4u);
  if (path.at("status") != "reached_bound") {
    EXPECT_EQ(path.at("reason"), "interrupted (SIGTERM)") << path.dump(1);
  }
  const nlohmann::json summary = nlohmann::json::parse(read_file(out / "sweep.json"));
  ASSERT_EQ(summary.at("cases").size(), 3u);
  int not_run = 0;
  for (const auto& row : summary.at("cases")) not_run += row.at("status") == "not_run" ? 1 : 0;
  EXPECT_GE(not_run, 1) << summary.dump(1);
  EXPECT_TRUE(fs::exists(out / "sweep.csv"));

  const auto rerun = run_cli("sweep '" + study.string() + "' -j 1 --out '" + out.string() + "'");
  EXPECT_EQ(rerun.exit_code, 0) << rerun.output;
}

// The same request delivered twice within a second (a scheduler signals every process of the
// job, and a sweep forwards the signal to its cases) stops the run gracefully, once.
TEST(RunInterrupts, RepeatedSigtermWithinASecondIsOneRequest) {
  const BackgroundRun run = start_run("interrupt_twice", "path_0003.vtu");
  ASSERT_TRUE(run.started) << read_file(run.log);
  kill(run.process.pid, SIGTERM);
  kill(run.process.pid, SIGTERM);
  const int code = wait_for(run.process);
  const std::string log = read_file(run.log);
  if (code == 0) GTEST_SKIP() << "the run ended before the signal arrived:\n" << log;
  EXPECT_EQ(code, 1) << log;  // not -SIGTERM: the second delivery did not end it at once
  EXPECT_TRUE(contains(log, "interrupted (SIGTERM)")) << log;
  EXPECT_TRUE(fs::exists(run.out / "path.json"));
}

}  // namespace
}  // namespace si
