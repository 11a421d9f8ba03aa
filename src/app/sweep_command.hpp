// `shellindent sweep STUDY.yaml [-j N] [--out DIR] [--quick]`: runs every case of a parameter
// study (io/study_file.hpp, docs/sweeps.md) as `shellindent run` would, each in
// DIR/cases/NNN_<slug>/ (with its generated case.yaml and the run's log run.log), at most N at
// once as child processes of the same executable (one assembly thread each). A case whose
// directory holds a finished path.json for the same case text is not run again, so a killed sweep
// resumes where it stopped. Prints a line per finished case to `err`, and writes DIR/sweep.csv
// and DIR/sweep.json: one row per case with the varied values, status, force at depth_max, the
// force maximum, the end energy, the critical-force events and (with `fit:`) the contact law
// T = C1 h^C2 with 95 % intervals. Returns 1 if a case failed; bad input throws (exit 2).
#pragma once

#include <ostream>
#include <string>

namespace si {

struct SweepCommandOptions {
  std::string study_file;
  std::string out_dir;                        // empty: results/<study name>/
  int jobs = 1;                               // cases run at once
  bool quick = false;                         // apply the study's `quick:` keys (smoke tests)
  std::string executable = "/proc/self/exe";  // the shellindent that runs each case
};

int run_sweep_command(const SweepCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace si
