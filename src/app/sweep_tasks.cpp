#include "app/sweep_tasks.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <utility>

#include "app/sweep_cases.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/output_directory.hpp"
#include "io/output_lock.hpp"
#include "io/sweep_table.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kRecord = "sweep_tasks.json";
constexpr const char* kTasks = "tasks.txt";

// A word for the shell: single quotes, a quote inside as '\''.
std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The command `shellindent sweep` spawns for a case (app/sweep_command.cpp), as one shell line.
std::string task_line(const std::string& exe, const fs::path& dir) {
  const std::string d = dir.string();
  return shell_quoted(exe) + " run " + shell_quoted((dir / "case.yaml").string()) + " --out " +
         shell_quoted(d) + " --threads 1 > " + shell_quoted((dir / "run.log").string()) + " 2>&1";
}

std::string readme(const fs::path& root, std::size_t tasks, std::size_t cases,
                   const std::string& study) {
  const std::string file = (root / kTasks).string();
  std::ostringstream os;
  os << "Cases of " << study << ", emitted by `shellindent sweep --emit` (docs/sweeps.md).\n"
     << kTasks << " holds " << tasks << " task(s), one shell command per line, for the " << cases
     << " case(s) not done yet; each runs one case on one thread.\n\n"
     << "A SLURM job array (line N is task N):\n"
     << "  sbatch --array=1-" << tasks << " --cpus-per-task=1 --wrap \\\n"
     << "    'sed -n \"${SLURM_ARRAY_TASK_ID}p\" " << file << " | bash'\n\n"
     << "GNU parallel, 8 at a time:\n"
     << "  parallel -j 8 < " << file << "\n\n"
     << "By hand, one after another:\n"
     << "  bash " << file << "\n\n"
     << "Then merge the results into sweep.csv and sweep.json:\n"
     << "  shellindent sweep --collect " << root.string() << "\n";
  return os.str();
}

bool is_empty_directory(const fs::path& dir) {
  return !fs::exists(dir) || (fs::is_directory(dir) && fs::is_empty(dir));
}

std::string absolute_text(const std::string& path) {
  return fs::weakly_canonical(fs::absolute(path)).string();
}

}  // namespace

int emit_sweep_tasks(const SweepCommandOptions& o, std::ostream& out, std::ostream& err) {
  if (!o.out_dir.empty())
    throw_input("--emit DIR is the output directory: give no --out",
                Where{"command line", "--out", o.out_dir, 0});
  const SweepCases s = load_sweep_cases(o.study_file, o.quick);
  const fs::path root = fs::weakly_canonical(fs::absolute(o.emit_dir));
  const Where where{"command line", "--emit", o.emit_dir, 0};
  const std::string study_path = absolute_text(o.study_file);
  if (!is_empty_directory(root)) {
    const std::optional<json> record = read_json_file(root / kRecord);
    if (!record)
      throw_input("the directory is not empty and holds no emitted sweep (" + std::string(kRecord) +
                      "): emit into a new or empty directory",
                  where);
    if (record->value("study_path", "") != study_path)
      throw_input("the directory holds the emitted sweep of another study, " +
                      record->value("study_path", "?") + ": emit into a new or empty directory",
                  where);
  }
  prepare_output_directory(root, where);
  const OutputLock lock(root, where);
  const std::string exe = resolve_executable(o.executable);
  std::string tasks;
  std::size_t count = 0;
  for (const StudyCase& c : s.cases) {
    const CaseState state = prepare_case_directory(root / "cases", c);
    if (state == CaseState::kDone) continue;
    if (state == CaseState::kStale) err << stale_case_note(c);
    tasks += task_line(exe, root / "cases" / c.slug) + "\n";
    ++count;
  }
  const json record{{"study", o.study_file}, {"study_path", study_path}, {"base", s.study.base},
                    {"quick", o.quick},      {"cases", s.cases.size()},  {"tasks", count},
                    {"executable", exe}};
  write_file_atomically((root / kTasks).string(), tasks);
  write_file_atomically((root / "README.txt").string(),
                        readme(root, count, s.cases.size(), o.study_file));
  write_file_atomically((root / kRecord).string(), record.dump(2) + "\n");
  out << readme(root, count, s.cases.size(), o.study_file);
  err << "sweep: " << o.study_file << ": " << s.cases.size() << " case(s)"
      << (o.quick ? " (--quick)" : "") << ", " << count << " task(s) written to "
      << (root / kTasks).string() << "\n";
  return 0;
}

int collect_sweep_tasks(const SweepCommandOptions& o, std::ostream& out, std::ostream& err) {
  const fs::path root(o.collect_dir);
  const Where where{"command line", "--collect", o.collect_dir, 0};
  const std::optional<json> record = read_json_file(root / kRecord);
  if (!record)
    throw_input("no emitted sweep here (" + std::string(kRecord) +
                    " is missing): write one with `shellindent sweep STUDY --emit DIR`",
                where);
  const std::string study_path = record->value("study_path", "");
  if (!o.study_file.empty() && absolute_text(o.study_file) != study_path)
    throw_input("the directory holds the emitted sweep of " + study_path + ", not of this study",
                Where{"command line", "study", o.study_file, 0});
  // Read from its absolute path, named as at --emit: the case texts and sweep.json name it so.
  StudyFile study = read_study_file(study_path);
  study.file = record->value("study", study.file);
  study.base = record->value("base", study.base);
  const SweepCases s = expand_sweep_cases(std::move(study), record->value("quick", false));
  const fs::path case_root = root / "cases";
  for (const StudyCase& c : s.cases) {
    std::ifstream in(case_root / c.slug / "case.yaml");
    std::ostringstream text;
    text << in.rdbuf();
    if (text.str() != c.yaml)
      throw_input("case " + std::to_string(c.index) + " (" + c.slug +
                      "): its case.yaml differs from the study's case (the study or its base "
                      "changed since --emit): emit again",
                  where);
  }
  const OutputLock lock(root, where);
  json rows = json::array();
  for (const StudyCase& c : s.cases) {
    const fs::path dir = case_root / c.slug;
    if (fs::exists(dir / "path.json") || fs::exists(dir / "run.log")) {
      rows.push_back(summarize_case(c, dir, s.study));
      continue;
    }
    json row{{"case", c.index}};
    for (const auto& [key, value] : c.values) row[key] = value;
    row["status"] = "not_run";
    row["reason"] = "its task has not run (no run.log in cases/" + c.slug + ")";
    rows.push_back(row);
  }
  err << "sweep: collected " << s.cases.size() << " case(s) of " << s.study.file << " from "
      << case_root.string() << "\n";
  return write_sweep_tables(root, s, rows, "not finished (failed or not run)", out, err);
}

}  // namespace si
