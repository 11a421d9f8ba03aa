// A sweep run by a batch system instead of by `shellindent sweep` itself (docs/sweeps.md):
//
//   shellindent sweep STUDY.yaml --emit DIR [--quick]    writes DIR/cases/NNN_<values>/case.yaml
//                                                        and DIR/tasks.txt, one shell command
//                                                        per case, runs nothing
//   sed -n "${SLURM_ARRAY_TASK_ID}p" DIR/tasks.txt | bash     (a SLURM job array, --array=1-N)
//   parallel -j 8 < DIR/tasks.txt                             (GNU parallel)
//   shellindent sweep --collect DIR                      merges the cases' results into
//                                                        DIR/sweep.csv and sweep.json
//
// Each task is the command `shellindent sweep` would spawn (`shellindent run CASE --out CASEDIR
// --threads 1`, output to CASEDIR/run.log), with absolute paths, so the merged table is the one
// `shellindent sweep -j N` writes. DIR/sweep_tasks.json records the study (its absolute path
// and the quick mode) for --collect; DIR/README.txt says how to run the tasks. Cases already
// done (the same case.yaml, a finished path.json) get no task: emitting again after some tasks
// ran lists only the rest. --collect reports a case that has not run (no run.log) as `not_run`,
// one that ran without a path.json as `failed` with its log's last line, as a sweep does.
#pragma once

#include <ostream>

#include "app/sweep_command.hpp"

namespace si {

// --emit: refuses a non-empty DIR that holds no emitted sweep of the same study file (exit 2).
int emit_sweep_tasks(const SweepCommandOptions& options, std::ostream& out, std::ostream& err);

// --collect: refuses a DIR without sweep_tasks.json, a study file other than the emitted one,
// and cases whose case.yaml no longer matches the study (exit 2). Returns 0 when every case
// finished, else 1.
int collect_sweep_tasks(const SweepCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace si
