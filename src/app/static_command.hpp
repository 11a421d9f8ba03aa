// `shellindent static CASE.yaml [--out DIR]`: a load-controlled static run of a shell without
// contact, from a case file with a `load` section (docs/case-file.md). Prints one progress line
// per converged step to `err` and a table to `out`; after the run writes DIR/static.csv,
// DIR/static.json and DIR/static.vtu (the last converged step, with the nodal strains and the
// resultants N, M, Q averaged over elements: model/nodal_resultants.hpp). Each file is written
// atomically, and only once the run has ended; a run that fails mid-way writes its converged steps,
// says where and why it stopped, and returns 1.
#pragma once

#include <ostream>
#include <string>

namespace si {

struct StaticCommandOptions {
  std::string case_file;
  std::string out_dir;  // empty: the case's output.dir
  int threads = 0;      // 0: OpenMP's default
};

// Returns the process exit code (0, or 1 if a step failed to converge); throws si::Error (input)
// on a bad case.
int run_static_command(const StaticCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace si
