// The merged table of a parameter study (docs/sweeps.md): one row per case, read from the files
// the case's run left in its directory (path.json, path_grid.csv, run.log), and sweep.csv /
// sweep.json made of the rows. Shared by `shellindent sweep` (app/sweep_command.cpp), which runs
// the cases as child processes, and the Python module's sweep (python/), which runs them on a
// Dask cluster: both write the same table.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/study_file.hpp"

namespace si {

// A JSON file's content; nothing if it is missing or not JSON.
std::optional<nlohmann::json> read_json_file(const std::filesystem::path& file);

// The run statuses of a path that reached its end ("completed", "reached_bound").
bool finished_status(const std::string& status);

// Where a case of a sweep stands: done when its directory holds the same case text (case.yaml)
// and a finished path.json written by this build (the same source fingerprint,
// io/source_fingerprint.hpp); a finished path.json of another build (or of one before the
// fingerprint was recorded) is stale: the sweep runs the case again and says why.
enum class CaseState { kToRun, kDone, kStale };
CaseState case_state(const std::filesystem::path& dir, const std::string& yaml);
const char* case_state_name(CaseState state);  // "to_run", "done", "stale"

// The last non-empty line of the case's run.log: why a run that wrote no path.json failed.
std::string last_log_line(const std::filesystem::path& dir);

// One row of sweep.json/sweep.csv from the case's path.json (and path_grid.csv for the fit).
nlohmann::json summarize_case(const StudyCase& c, const std::filesystem::path& dir,
                              const StudyFile& study);

// The table's columns: case, the varied keys, status ..., the damage columns the cases ask for
// (io/damage_summary.hpp) and with `fit:` the contact law's.
std::vector<std::string> sweep_columns(const StudyFile& study, const std::vector<StudyCase>& cases);

// sweep.csv and sweep.json of the rows (one per case of `cases`, in case order).
std::string sweep_csv(const StudyFile& study, const std::vector<StudyCase>& cases,
                      const nlohmann::json& rows);
std::string sweep_json(const StudyFile& study, const std::vector<StudyCase>& cases, bool quick,
                       const nlohmann::json& rows);

}  // namespace si
