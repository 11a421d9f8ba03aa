// `shellindent sweep STUDY.yaml --scheduler tcp://host:8786`: the cases run on an existing Dask
// cluster by the Python module's sweep (python/shellindent/sweep.py, docs/python.md), which the
// CLI starts as `python3 -m shellindent.sweep_cli` (the interpreter the module was built for, or
// $SHELLINDENT_PYTHON; the build tree's python/ put first on PYTHONPATH when it holds the
// module). The study is read and checked here first (bad input: exit 2 before Python starts),
// and the output directory is locked while the child runs. A missing module, a missing
// dask.distributed, or a scheduler that cannot be reached within the connect timeout is an
// input error naming --scheduler (exit 2). Ctrl-C and SIGTERM are passed on to the child as
// Ctrl-C: it stops waiting for the cluster and leaves the finished cases for a rerun.
#pragma once

#include <ostream>

#include "app/sweep_command.hpp"

namespace si {

// The child's exit code: 0 every case finished, 1 a case failed (or interrupted), 2 bad input.
int run_dask_sweep(const SweepCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace si
