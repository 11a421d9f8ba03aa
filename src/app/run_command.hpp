// `shellindent run [CASE.yaml] [--out DIR] [--threads N]`: the indentation depth path of a case
// (analysis/indentation_run.hpp). Without a case file it runs the built-in default, the source
// paper's cap with [0/0]2S (io/default_case.hpp). Prints a progress line per converged point to
// `err` and the force-depth table to `out`; writes DIR/path.csv, DIR/path.json, DIR/events.json
// and VTU files of chosen points (output.vtu_every) with a ParaView collection DIR/path.pvd, each
// file atomically. Continuation runs also keep DIR/checkpoint.json (every 10 points) and
// `--resume` continues from it. A run that stops early (no convergence at the minimum step, Ctrl-C)
// keeps and writes every converged point, says where and why it stopped, and returns 1.
#pragma once

#include <ostream>
#include <string>

namespace si {

struct RunCommandOptions {
  std::string case_file;  // empty: the built-in default case
  std::string out_dir;    // empty: the case's output.dir
  int threads = 0;        // 0: OpenMP's default
  bool resume = false;    // continue from DIR/checkpoint.json (continuation runs)
};

int run_run_command(const RunCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace si
