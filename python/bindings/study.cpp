// A parameter study for the Python sweep (shellindent/sweep.py): the study file read and its
// cases expanded by io/study_file as `shellindent sweep` does, and the merged table made by
// io/sweep_table from the case directories, so that both write the same sweep.csv.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "io/path_results.hpp"
#include "io/source_fingerprint.hpp"
#include "io/sweep_table.hpp"

namespace si::py {
namespace {

struct StudyHandle {
  StudyFile file;
  std::vector<StudyCase> cases;
  bool quick = false;
};

py::list case_list(const StudyHandle& s) {
  py::list out;
  for (const StudyCase& c : s.cases) {
    py::dict d;
    d["index"] = c.index;
    d["label"] = c.label;
    d["slug"] = c.slug;
    d["yaml"] = c.yaml;
    d["values"] = c.values;
    out.append(d);
  }
  return out;
}

nlohmann::json rows_of(const StudyHandle& s, const std::vector<std::string>& dirs) {
  if (dirs.size() != s.cases.size())
    throw_input("one directory per case expected (" + std::to_string(s.cases.size()) + "), got " +
                std::to_string(dirs.size()));
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < dirs.size(); ++i)
    rows.push_back(summarize_case(s.cases[i], dirs[i], s.file));
  return rows;
}

}  // namespace

void bind_study(py::module_& m) {
  py::class_<StudyHandle>(m, "Study", "A parameter study read by the study-file reader")
      .def_property_readonly("name", [](const StudyHandle& s) { return s.file.name; })
      .def_property_readonly("file", [](const StudyHandle& s) { return s.file.file; })
      .def_property_readonly("quick", [](const StudyHandle& s) { return s.quick; })
      .def_property_readonly("cases", &case_list)
      .def(
          "tables",
          [](const StudyHandle& s, const std::vector<std::string>& dirs) {
            const nlohmann::json rows = rows_of(s, dirs);
            return py::make_tuple(sweep_csv(s.file, s.cases, rows),
                                  sweep_json(s.file, s.cases, s.quick, rows));
          },
          py::arg("case_dirs"), "(sweep.csv, sweep.json) of the cases' directories");
  m.def(
      "read_study",
      [](const std::string& path, bool quick) {
        StudyHandle s{read_study_file(path), {}, quick};
        s.cases = expand_study(s.file, quick);
        return s;
      },
      py::arg("path"), py::arg("quick") = false);
  m.def(
      "case_state",
      [](const std::string& dir, const std::string& yaml) {
        return std::string(case_state_name(case_state(dir, yaml)));
      },
      py::arg("dir"), py::arg("yaml"),
      "'done' (skip), 'stale' (another build wrote its results: run again) or 'to_run'");
  m.def(
      "source_fingerprint", [] { return std::string(source_fingerprint()); },
      "SHA-256 of the sources and build settings of this module (path.json's build record)");
}

}  // namespace si::py
