// What the ways of running a sweep share (docs/sweeps.md): the study's cases read and checked,
// a case's directory made ready to run, and the merged table written. A sweep runs its cases
// as child processes (app/sweep_command.cpp), as a task list for a SLURM job array or GNU
// parallel (app/sweep_tasks.cpp), or on a Dask cluster (app/dask_sweep.cpp); each ends with the
// same sweep.csv and sweep.json (io/sweep_table.hpp).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "io/study_file.hpp"
#include "io/sweep_table.hpp"

namespace si {

struct SweepCases {
  StudyFile study;
  std::vector<StudyCase> cases;
  bool quick = false;
};

// Reads the study and builds every case (io/study_file.hpp); a case whose output.formats lacks
// json is refused (the table is read from path.json). Input errors throw.
SweepCases load_sweep_cases(const std::string& study_file, bool quick);
// The same for a study already read.
SweepCases expand_sweep_cases(StudyFile study, bool quick);

// Makes DIR/<slug> ready for the case to run: removes a previous run's results and log and
// writes its case.yaml. Returns what it found (io/sweep_table.hpp case_state) and touches nothing
// when the case is done already: a sweep started again does not run it again. A stale case (its
// results from another build) is prepared to run again.
CaseState prepare_case_directory(const std::filesystem::path& case_root, const StudyCase& c);

// The line a sweep prints for a case it runs again because another build wrote its results.
std::string stale_case_note(const StudyCase& c);

// Writes ROOT/sweep.csv and sweep.json of `rows` (one per case, in order), prints the table to
// `out` and what was written to `err`; returns 0 when every case finished, else 1, saying that
// so many cases are `unfinished` ("failed", "not finished: interrupted (Ctrl-C)").
int write_sweep_tables(const std::filesystem::path& root, const SweepCases& s,
                       const nlohmann::json& rows, const std::string& unfinished, std::ostream& out,
                       std::ostream& err);

}  // namespace si
