#include "app/sweep_command.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "analysis/path_columns.hpp"
#include "app/dask_sweep.hpp"
#include "app/interrupt_signals.hpp"
#include "app/sweep_cases.hpp"
#include "app/sweep_tasks.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/output_directory.hpp"
#include "io/output_lock.hpp"
#include "io/path_results.hpp"
#include "io/study_file.hpp"
#include "io/sweep_table.hpp"
#include "io/thread_count.hpp"

extern char** environ;

namespace si {

namespace fs = std::filesystem;

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

// `EXE run DIR/case.yaml --out DIR --threads 1`, stdout and stderr to DIR/run.log; no shell.
pid_t spawn_case(const std::string& exe, const fs::path& dir) {
  const std::string case_file = (dir / "case.yaml").string();
  const std::string out = dir.string();
  const std::string log = (dir / "run.log").string();
  std::vector<std::string> args{exe, "run", case_file, "--out", out, "--threads", "1"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw Error(ErrorKind::kInternal, "cannot start '" + exe + "': " + std::strerror(rc));
  return pid;
}

struct Running {
  size_t index;
  Clock::time_point start;
};

class Scheduler {
 public:
  Scheduler(const std::vector<StudyCase>& cases, const fs::path& root, int jobs, std::string exe,
            std::ostream& err)
      : cases_(cases), root_(root), jobs_(std::max(jobs, 1)), exe_(std::move(exe)), err_(err) {}

  // Runs `todo`, `jobs_` at a time. On Ctrl-C or SIGTERM (InterruptGuard of the command) it
  // starts nothing more and passes SIGTERM on to the running cases, which stop after their
  // current point and write what converged; it waits for them, so the summary that follows
  // holds their points. Polls (WNOHANG) because the handlers restart an interrupted waitpid.
  void run(const std::vector<size_t>& todo) {
    size_t next = 0;
    bool forwarded = false;
    while (true) {
      while (!interrupted() && next < todo.size() && static_cast<int>(running_.size()) < jobs_) {
        const size_t i = todo[next++];
        running_[spawn_case(exe_, root_ / cases_[i].slug)] = Running{i, Clock::now()};
      }
      if (interrupted() && !forwarded) {
        forward_interrupt();
        forwarded = true;
      }
      if (running_.empty()) break;
      int status = 0;
      const pid_t pid = waitpid(-1, &status, WNOHANG);
      if (pid == 0 || (pid < 0 && errno == EINTR)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        continue;
      }
      if (pid < 0) break;
      const auto it = running_.find(pid);
      if (it == running_.end()) continue;
      report(it->second, status);
      running_.erase(it);
    }
    for (; next < todo.size(); ++next) not_started_.insert(todo[next]);
  }
  // Cases an interrupt kept from starting.
  bool started(size_t i) const { return not_started_.count(i) == 0; }
  void report_skipped(size_t i) {
    ++done_;
    err_ << "sweep: " << done_ << "/" << cases_.size() << " " << cases_[i].label
         << ": already done, skipped\n";
  }

 private:
  void forward_interrupt() {
    err_ << "sweep: interrupted (" << interrupt_name() << "): starting no more cases; "
         << running_.size() << " running case(s) stop after their current point" << std::endl;
    for (const auto& [pid, r] : running_) kill(pid, SIGTERM);
  }

  void report(const Running& r, int status) {
    ++done_;
    const double seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
    const fs::path dir = root_ / cases_[r.index].slug;
    const std::optional<json> path = read_json_file(dir / "path.json");
    std::string what = path ? path->value("status", "?") : "failed: " + last_log_line(dir);
    if (!WIFEXITED(status)) what = "failed: killed by a signal";
    char time[32];
    std::snprintf(time, sizeof time, "%.1f s", seconds);
    err_ << "sweep: " << done_ << "/" << cases_.size() << " " << cases_[r.index].label << ": "
         << what << ", " << time << std::endl;
  }

  const std::vector<StudyCase>& cases_;
  fs::path root_;
  int jobs_;
  std::string exe_;
  std::ostream& err_;
  std::map<pid_t, Running> running_;
  std::set<size_t> not_started_;
  int done_ = 0;
};

// The row of a case an interrupt kept from starting; a rerun of the sweep runs it.
json not_run(const StudyCase& c, const std::string& signal) {
  json row;
  row["case"] = c.index;
  for (const auto& [key, value] : c.values) row[key] = value;
  row["status"] = "not_run";
  row["reason"] = "the sweep was interrupted (" + signal + ") before this case started";
  return row;
}

// The cases run here, -j at a time, as child processes.
int run_local_sweep(const SweepCommandOptions& o, std::ostream& out, std::ostream& err) {
  check_parallel_count(o.jobs, "-j", 1, "cases at once");
  const SweepCases s = load_sweep_cases(o.study_file, o.quick);
  const fs::path root = sweep_root(o, s.study);
  const Where root_where = sweep_root_where(o, s.study);
  prepare_output_directory(root, root_where);
  const OutputLock lock(root, root_where);
  const fs::path case_root = root / "cases";
  err << "sweep: " << s.study.file << ": " << s.cases.size() << " case(s)"
      << (o.quick ? " (--quick)" : "") << ", " << o.jobs << " at once, in " << case_root.string()
      << "\n";
  const InterruptGuard guard;  // Ctrl-C / SIGTERM: stop the cases, then summarise (Scheduler)
  Scheduler scheduler(s.cases, case_root, o.jobs, resolve_executable(o.executable), err);
  std::vector<size_t> todo;
  for (size_t i = 0; i < s.cases.size(); ++i) {
    const CaseState state = prepare_case_directory(case_root, s.cases[i]);
    if (state == CaseState::kDone) {
      scheduler.report_skipped(i);
      continue;
    }
    if (state == CaseState::kStale) err << stale_case_note(s.cases[i]);
    todo.push_back(i);
  }
  scheduler.run(todo);

  json rows = json::array();
  for (size_t i = 0; i < s.cases.size(); ++i)
    rows.push_back(scheduler.started(i)
                       ? summarize_case(s.cases[i], case_root / s.cases[i].slug, s.study)
                       : not_run(s.cases[i], interrupt_name()));
  return write_sweep_tables(
      root, s, rows,
      interrupted() ? std::string("not finished: interrupted (") + interrupt_name() + ")"
                    : std::string("failed"),
      out, err);
}

}  // namespace

fs::path sweep_root(const SweepCommandOptions& o, const StudyFile& study) {
  return o.out_dir.empty() ? fs::path("results") / study.name : fs::path(o.out_dir);
}

Where sweep_root_where(const SweepCommandOptions& o, const StudyFile& study) {
  return o.out_dir.empty() ? Where{study.file, "name", study.name, 0}
                           : Where{"command line", "--out", o.out_dir, 0};
}

std::string resolve_executable(const std::string& exe) {
  if (exe != "/proc/self/exe") return exe;
  std::error_code ec;
  const fs::path p = fs::read_symlink(exe, ec);
  return ec ? exe : p.string();
}

int run_sweep_command(const SweepCommandOptions& o, std::ostream& out, std::ostream& err) {
  const int modes = !o.emit_dir.empty() + !o.collect_dir.empty() + !o.scheduler.empty();
  if (modes > 1)
    throw_input("--emit, --collect and --scheduler exclude each other: give one",
                Where{"command line", "sweep", "", 0});
  if (!o.collect_dir.empty()) {
    if (o.quick)
      throw_input("--collect takes the quick mode from the emitted sweep: give no --quick",
                  Where{"command line", "--quick", "", 0});
    return collect_sweep_tasks(o, out, err);
  }
  if (o.study_file.empty())
    throw_input("a study file is required (only --collect DIR finds it in DIR)",
                Where{"command line", "study", "", 0});
  if (!o.emit_dir.empty()) return emit_sweep_tasks(o, out, err);
  if (!o.scheduler.empty()) return run_dask_sweep(o, out, err);
  return run_local_sweep(o, out, err);
}

}  // namespace si
