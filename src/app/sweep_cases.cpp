#include "app/sweep_cases.hpp"

#include <algorithm>
#include <utility>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/sweep_table.hpp"

namespace si {

namespace fs = std::filesystem;

SweepCases load_sweep_cases(const std::string& study_file, bool quick) {
  return expand_sweep_cases(read_study_file(study_file), quick);
}

SweepCases expand_sweep_cases(StudyFile study, bool quick) {
  SweepCases s{std::move(study), {}, quick};
  s.cases = expand_study(s.study, quick);
  for (const StudyCase& c : s.cases)  // the sweep's table is read from each case's path.json
    if (std::find(c.case_file.output.formats.begin(), c.case_file.output.formats.end(),
                  OutputFormat::kJson) == c.case_file.output.formats.end())
      throw_input("a sweep reads each case's path.json: output.formats must include json",
                  Where{c.label, "output.formats", "", 0});
  return s;
}

CaseState prepare_case_directory(const fs::path& case_root, const StudyCase& c) {
  const fs::path dir = case_root / c.slug;
  const CaseState state = case_state(dir, c.yaml);
  if (state == CaseState::kDone) return state;
  for (const char* stale :
       {"path.json", "path.csv", "path_grid.csv", "events.json", "checkpoint.json", "run.log"})
    fs::remove(dir / stale);
  write_file_atomically((dir / "case.yaml").string(), c.yaml);
  return state;
}

std::string stale_case_note(const StudyCase& c) {
  return "sweep: " + c.label +
         ": its results were written by another build of shellindent (or one that did not record "
         "its source fingerprint): run again\n";
}

int write_sweep_tables(const fs::path& root, const SweepCases& s, const nlohmann::json& rows,
                       const std::string& unfinished, std::ostream& out, std::ostream& err) {
  int failed = 0;
  for (const nlohmann::json& row : rows)
    failed += finished_status(row["status"].get<std::string>()) ? 0 : 1;
  const std::string csv = sweep_csv(s.study, s.cases, rows);
  write_file_atomically((root / "sweep.csv").string(), csv);
  write_file_atomically((root / "sweep.json").string(),
                        sweep_json(s.study, s.cases, s.quick, rows));
  out << csv;
  err << "wrote " << (root / "sweep.csv").string() << " and sweep.json";
  if (failed == 0) {
    err << "\n";
    return 0;
  }
  err << "; " << failed << " of " << s.cases.size() << " case(s) " << unfinished << "\n";
  return 1;
}

}  // namespace si
