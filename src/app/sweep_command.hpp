// `shellindent sweep STUDY.yaml [-j N] [--out DIR] [--quick]`: runs every case of a parameter
// study (io/study_file.hpp, docs/sweeps.md) as `shellindent run` would, each in
// DIR/cases/NNN_<slug>/ (with its generated case.yaml and the run's log run.log), at most N at
// once as child processes of the same executable (one assembly thread each). A case whose
// directory holds a finished path.json for the same case text is not run again, so a killed sweep
// resumes where it stopped. Prints a line per finished case to `err`, and writes DIR/sweep.csv
// and DIR/sweep.json: one row per case with the varied values, status, force at depth_max, the
// force maximum, the end energy, the critical-force events and (with `fit:`) the contact law
// T = C1 h^C2 with 95 % intervals. Returns 1 if a case failed; bad input throws (exit 2).
// Instead of running the cases here: `--emit DIR` writes them with a task list for a SLURM job
// array or GNU parallel and `--collect DIR` merges what those runs left (app/sweep_tasks.hpp);
// `--scheduler ADDRESS` runs them on a Dask cluster (app/dask_sweep.hpp).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

#include "core/error.hpp"
#include "io/study_file.hpp"

namespace si {

struct SweepCommandOptions {
  std::string study_file;
  std::string out_dir;                        // empty: results/<study name>/
  int jobs = 1;                               // cases run at once
  bool quick = false;                         // apply the study's `quick:` keys (smoke tests)
  std::string executable = "/proc/self/exe";  // the shellindent that runs each case
  std::string emit_dir;     // --emit DIR: write the cases and tasks.txt, run nothing
  std::string collect_dir;  // --collect DIR: merge the results of an emitted sweep
  std::string scheduler;    // --scheduler ADDRESS: run the cases on that Dask cluster
};

int run_sweep_command(const SweepCommandOptions& options, std::ostream& out, std::ostream& err);

// The sweep's output directory (--out, default results/<study name>/) and where to blame it.
std::filesystem::path sweep_root(const SweepCommandOptions& options, const StudyFile& study);
Where sweep_root_where(const SweepCommandOptions& options, const StudyFile& study);
// The executable's own path for "/proc/self/exe" (what the cases run), else `exe`.
std::string resolve_executable(const std::string& exe);

}  // namespace si
