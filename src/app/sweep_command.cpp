#include "app/sweep_command.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "analysis/path_columns.hpp"
#include "app/damage_summary.hpp"
#include "app/interrupt_signals.hpp"
#include "app/thread_count.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "fitting/builtin_models.hpp"
#include "fitting/curve_model.hpp"
#include "io/csv_table.hpp"
#include "io/output_directory.hpp"
#include "io/output_lock.hpp"
#include "io/path_results.hpp"
#include "io/study_file.hpp"

extern char** environ;

namespace si {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::optional<json> read_json(const fs::path& p) {
  if (!fs::is_regular_file(p)) return std::nullopt;
  try {
    return json::parse(read_text(p));
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

bool finished(const std::string& status) {
  return status == run_status_name(RunStatus::kCompleted) ||
         status == run_status_name(RunStatus::kReachedBound);
}

// The path columns the summary reads (analysis/path_columns.hpp).
const char* depth_column() {
  return column_name(PathColumn::kDepth);
}
const char* force_column() {
  return column_name(PathColumn::kForce);
}

// A case is done when its directory holds the same case text and a finished path.json.
bool case_is_done(const fs::path& dir, const std::string& yaml) {
  if (!fs::is_regular_file(dir / "case.yaml") || read_text(dir / "case.yaml") != yaml) return false;
  const std::optional<json> path = read_json(dir / "path.json");
  return path && finished(path->value("status", ""));
}

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

// The last non-empty line of the case's log: why a run that wrote no path.json failed.
std::string last_log_line(const fs::path& dir) {
  std::istringstream in(read_text(dir / "run.log"));
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no output (see run.log)" : last;
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
    const std::optional<json> path = read_json(dir / "path.json");
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

// Linear interpolation of column `y` at depth `d` on the first passage; NaN if not reached.
double value_at_depth(const json& points, const char* y, double d) {
  for (size_t i = 0; i < points.size(); ++i) {
    const double d0 = points[i][depth_column()];
    if (std::abs(d0 - d) <= 1e-9 * (1 + d)) return points[i][y];
    if (i + 1 < points.size()) {
      const double d1 = points[i + 1][depth_column()];
      if ((d - d0) * (d - d1) < 0) {
        const double t = (d - d0) / (d1 - d0);
        return (1 - t) * points[i][y].get<double>() + t * points[i + 1][y].get<double>();
      }
    }
  }
  return kNaN;
}

// The first inflection of T_N against the column `against` (k11): {depth, force} or NaNs.
std::pair<double, double> first_inflection(const json& events, PathColumn against) {
  const std::string inflection = cont::event_type_name(cont::EventType::kInflection);
  for (const json& e : events)
    if (e.value("type", "") == inflection && e.value("monitor", "") == force_column() &&
        e.value("against", "") == column_name(against))
      return {e.value(depth_column(), kNaN), e.value(force_column(), kNaN)};
  return {kNaN, kNaN};
}

// The case's path_grid.csv (pseudo-arclength runs: the force at the depth grid, interpolated on
// the branch by cubic Hermite, io/path_results.hpp) as points {depth_mm, force_N}; empty when
// the run wrote none (its points are then on the grid already).
json grid_points(const fs::path& dir) {
  json points = json::array();
  const fs::path file = dir / "path_grid.csv";
  if (!fs::exists(file)) return points;
  const CsvTable grid = read_csv_table(file.string());
  const std::vector<double> depth = grid.numeric_column(depth_column());
  const std::vector<double> force = grid.numeric_column(force_column());
  for (std::size_t i = 0; i < depth.size(); ++i)
    points.push_back({{depth_column(), depth[i]}, {force_column(), force[i]}});
  return points;
}

// T = C1 h^C2 by least squares in linear space over the study's depth range (fitting library),
// on the case's depth grid dh, 2 dh, ... (the paper's 0.1 mm stepping, P9): path_grid.csv's
// values where the points are adaptive (grid_points), read off `points` otherwise. Why the grid:
// adaptive points crowd where the step controller shrank the step (contact changes), which weights
// the fit towards those depths; on the [0/0]2S cap C2 moved from 1.61 (grid) to 1.79 (points).
void fit_contact_law(const json& points, const StudyFit& f, double dh, json& row) {
  std::vector<double> h, t;
  const double end = points.back()[depth_column()];
  for (long k = 1;; ++k) {
    const double d = static_cast<double>(k) * dh;
    if (d > f.depth_max * (1 + 1e-12) || d > end * (1 + 1e-12)) break;
    if (d <= f.depth_min) continue;
    const double force = value_at_depth(points, force_column(), d);
    if (!std::isfinite(force)) continue;
    h.push_back(d);
    t.push_back(force);
  }
  if (h.size() < 3) {
    row["fit_status"] = "too few points (" + std::to_string(h.size()) + ") in the fit range";
    return;
  }
  const Eigen::VectorXd x = Eigen::Map<Eigen::VectorXd>(h.data(), Eigen::Index(h.size()));
  const Eigen::VectorXd y = Eigen::Map<Eigen::VectorXd>(t.data(), Eigen::Index(t.size()));
  const fit::FitResult r = fit::fit_curve(fit::power_law(), x, y);
  row["fit_status"] = fit::to_string(r.status);
  row["C1"] = r.parameters[0];
  row["C1_lo"] = r.ci_lower[0];
  row["C1_hi"] = r.ci_upper[0];
  row["C2"] = r.parameters[1];
  row["C2_lo"] = r.ci_lower[1];
  row["C2_hi"] = r.ci_upper[1];
  row["R2"] = r.r_squared;
}

// One row of sweep.json/sweep.csv from the case's path.json.
json summarize(const StudyCase& c, const fs::path& dir, const StudyFile& study) {
  json row;
  row["case"] = c.index;
  for (const auto& [key, value] : c.values) row[key] = value;
  const std::optional<json> path = read_json(dir / "path.json");
  if (!path) {
    row["status"] = "failed";
    row["reason"] = last_log_line(dir);
    return row;
  }
  const json& pts = (*path)["points"];
  row["status"] = path->value("status", "");
  row["reason"] = path->value("reason", "");
  row["points"] = pts.size();
  if (pts.empty()) return row;
  const char* depth = depth_column();
  const char* force = force_column();
  row["depth_end_mm"] = pts.back()[depth];
  row["force_at_depth_max_N"] = value_at_depth(pts, force, c.case_file.path.depth_max);
  size_t imax = 0;
  for (size_t i = 0; i < pts.size(); ++i)
    if (pts[i][force].get<double>() > pts[imax][force].get<double>()) imax = i;
  row["max_force_N"] = pts[imax][force];
  row["depth_at_max_force_mm"] = pts[imax][depth];
  row["energy_end_Nmm"] = pts.back()[column_name(PathColumn::kEnergy)];
  const json events = (*path)["events"];
  for (const auto& [k, column] :
       {std::pair{"k11", PathColumn::kK11}, std::pair{"k22", PathColumn::kK22}}) {
    const auto [at_depth, at_force] = first_inflection(events, column);
    row[std::string("critical_") + k + "_depth_mm"] = at_depth;
    row[std::string("critical_") + k + "_force_N"] = at_force;
  }
  summarize_damage(*path, row);
  if (study.has_fit) {
    const json grid = grid_points(dir);
    fit_contact_law(grid.empty() ? pts : grid, study.fit, c.case_file.path.step, row);
  }
  return row;
}

// The row of a case an interrupt kept from starting; a rerun of the sweep runs it.
json not_run(const StudyCase& c, const std::string& signal) {
  json row;
  row["case"] = c.index;
  for (const auto& [key, value] : c.values) row[key] = value;
  row["status"] = "not_run";
  row["reason"] = "the sweep was interrupted (" + signal + ") before this case started";
  return row;
}

std::vector<std::string> columns(const StudyFile& study, const std::vector<StudyCase>& cases) {
  std::vector<std::string> cols{"case"};
  for (const auto& kv : study.vary) cols.push_back(kv.first);
  for (const char* c :
       {"status", "reason", "points", "depth_end_mm", "force_at_depth_max_N", "max_force_N",
        "depth_at_max_force_mm", "energy_end_Nmm", "critical_k11_depth_mm", "critical_k11_force_N",
        "critical_k22_depth_mm", "critical_k22_force_N"})
    cols.push_back(c);
  for (const std::string& c : damage_columns(cases)) cols.push_back(c);
  if (study.has_fit)
    for (const char* c : {"fit_status", "C1", "C1_lo", "C1_hi", "C2", "C2_lo", "C2_hi", "R2"})
      cols.push_back(c);
  return cols;
}

// A CSV cell: numbers with 10 significant digits (NaN and absent: empty), text quoted if needed.
std::string cell(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number()) {
    const double d = v.get<double>();
    if (!std::isfinite(d)) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", d);
    return buf;
  }
  const std::string s = v.is_string() ? v.get<std::string>() : v.dump();
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

std::string sweep_csv(const std::vector<std::string>& cols, const json& rows) {
  std::ostringstream os;
  for (size_t i = 0; i < cols.size(); ++i) os << (i ? "," : "") << cols[i];
  os << "\n";
  for (const json& row : rows) {
    for (size_t i = 0; i < cols.size(); ++i)
      os << (i ? "," : "") << (row.contains(cols[i]) ? cell(row[cols[i]]) : "");
    os << "\n";
  }
  return os.str();
}

std::string resolve_executable(const std::string& exe) {
  if (exe != "/proc/self/exe") return exe;
  std::error_code ec;
  const fs::path p = fs::read_symlink(exe, ec);
  return ec ? exe : p.string();
}

}  // namespace

int run_sweep_command(const SweepCommandOptions& o, std::ostream& out, std::ostream& err) {
  check_parallel_count(o.jobs, "-j", 1, "cases at once");
  const StudyFile study = read_study_file(o.study_file);
  const std::vector<StudyCase> cases = expand_study(study, o.quick);
  for (const StudyCase& c : cases)  // the sweep's table is read from each case's path.json
    if (std::find(c.case_file.output.formats.begin(), c.case_file.output.formats.end(),
                  OutputFormat::kJson) == c.case_file.output.formats.end())
      throw_input("a sweep reads each case's path.json: output.formats must include json",
                  Where{c.label, "output.formats", "", 0});
  const fs::path root = o.out_dir.empty() ? fs::path("results") / study.name : fs::path(o.out_dir);
  const Where root_where = o.out_dir.empty() ? Where{study.file, "name", study.name, 0}
                                             : Where{"command line", "--out", root.string(), 0};
  prepare_output_directory(root, root_where);
  const OutputLock lock(root, root_where);
  const fs::path case_root = root / "cases";
  err << "sweep: " << study.file << ": " << cases.size() << " case(s)"
      << (o.quick ? " (--quick)" : "") << ", " << o.jobs << " at once, in " << case_root.string()
      << "\n";
  const InterruptGuard guard;  // Ctrl-C / SIGTERM: stop the cases, then summarise (Scheduler)
  Scheduler scheduler(cases, case_root, o.jobs, resolve_executable(o.executable), err);
  std::vector<size_t> todo;
  for (size_t i = 0; i < cases.size(); ++i) {
    const fs::path dir = case_root / cases[i].slug;
    if (case_is_done(dir, cases[i].yaml)) {
      scheduler.report_skipped(i);
      continue;
    }
    for (const char* stale : {"path.json", "path.csv", "events.json", "checkpoint.json"})
      fs::remove(dir / stale);
    write_file_atomically((dir / "case.yaml").string(), cases[i].yaml);
    todo.push_back(i);
  }
  scheduler.run(todo);

  json rows = json::array();
  int failed = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    rows.push_back(scheduler.started(i) ? summarize(cases[i], case_root / cases[i].slug, study)
                                        : not_run(cases[i], interrupt_name()));
    failed += finished(rows.back()["status"].get<std::string>()) ? 0 : 1;
  }
  const std::vector<std::string> cols = columns(study, cases);
  const std::string csv = sweep_csv(cols, rows);
  write_file_atomically((root / "sweep.csv").string(), csv);
  const json doc{{"study", study.file},
                 {"name", study.name},
                 {"base", study.base},
                 {"quick", o.quick},
                 {"combine", study.zip ? "zip" : "product"},
                 {"columns", cols},
                 {"cases", rows}};
  write_file_atomically((root / "sweep.json").string(), doc.dump(2) + "\n");
  out << csv;
  err << "wrote " << (root / "sweep.csv").string() << " and sweep.json";
  if (failed == 0) {
    err << "\n";
    return 0;
  }
  err << "; " << failed << " of " << cases.size() << " case(s) "
      << (interrupted() ? std::string("not finished: interrupted (") + interrupt_name() + ")"
                        : std::string("failed"))
      << "\n";
  return 1;
}

}  // namespace si
