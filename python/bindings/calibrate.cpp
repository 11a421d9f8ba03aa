// A calibration of a case against a measured force-travel curve (shellindent.calibrate), by
// io/case_calibration as `shellindent calibrate` runs it: the same checks and error text, the
// same search, the same report (io/calibration_report: calibration.json, calibration_curve.csv,
// the table). The GIL is released during the runs and taken back after every evaluation (the
// progress function) and every converged point (signals): Ctrl-C or an exception of the
// progress function stops the calibration with the best point so far (status interrupted) and
// is handed back with the result, as run_case does.
#include <pybind11/stl.h>

#include <charconv>
#include <optional>
#include <sstream>

#include "bindings.hpp"
#include "io/calibration_report.hpp"
#include "io/case_calibration.hpp"
#include "io/csv_table.hpp"

namespace si::py {
namespace {

// The shortest text that reads back as exactly `v` (0.8, not 0.80000000000000004), so that a
// message quotes the value as the user wrote it.
std::string shortest_text(double v) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// Arrays given from Python as the table of a CSV file named `label` (travel_mm, force_N; the
// values written in their shortest exact form), checked by the same reader as a file.
CsvTable table_of_arrays(const std::string& label, const std::vector<double>& travel,
                         const std::vector<double>& force) {
  if (travel.size() != force.size())
    throw_input("travel and force differ in length (" + std::to_string(travel.size()) + " and " +
                    std::to_string(force.size()) + ")",
                Where{label, "data", "", 0});
  CsvTable t;
  t.file = label;
  t.names = {"travel_mm", "force_N"};
  t.header_line = 1;
  for (std::size_t i = 0; i < travel.size(); ++i) {
    t.rows.push_back({shortest_text(travel[i]), shortest_text(force[i])});
    t.lines.push_back(static_cast<int>(i) + 2);
  }
  return t;
}

py::dict progress_dict(const fit::CalibrationProgress& p, const CaseCalibration& c) {
  py::dict d;
  d["evaluation"] = p.evaluation;
  d["phase"] = p.phase == fit::CalibrationPhase::kSearch ? "search" : "jacobian";
  std::vector<double> values(p.parameters.data(), p.parameters.data() + p.parameters.size());
  d["parameters"] = values;
  d["ok"] = p.ok;
  d["sse"] = p.sse;
  d["best_sse"] = p.best_sse;
  d["seconds"] = p.seconds;
  d["failure"] = p.failure;
  d["line"] = c.progress_line(p);
  return d;
}

struct DataSource {
  std::string file, x_column, y_column;  // a CSV file, or
  std::string label;                     // arrays named `label`
  std::vector<double> travel, force;
};

py::tuple calibrate_case(const CaseHandle& c, const DataSource& data,
                         const std::vector<std::string>& params, const std::string& algorithm,
                         int max_evaluations, double xtol, int threads, int jobs, bool warm_start,
                         const py::object& progress) {
  const CaseCalibrationInput input{
      c.file.file, c.text, params,
      CaseCalibrationSettings{algorithm, max_evaluations, xtol, threads, jobs, warm_start}};
  std::ostringstream notes;
  std::optional<CaseCalibration> calibration;
  {
    py::gil_scoped_release nogil;
    calibration.emplace(
        input,
        [&](int min_points) {
          return data.file.empty()
                     ? measured_curve_from_table(
                           table_of_arrays(data.label, data.travel, data.force), "", "", min_points)
                     : read_measured_curve(data.file, data.x_column, data.y_column, min_points);
        },
        notes);
  }
  std::optional<py::error_already_set> pending;  // what stopped the calibration from Python
  // Called with the GIL held; false once something is pending.
  const auto check_signals = [&] {
    if (pending) return false;
    if (PyErr_CheckSignals() == 0) return true;
    pending.emplace();
    return false;
  };
  fit::CalibrationResult r;
  {
    py::gil_scoped_release nogil;
    r = calibration->run(
        [&](const fit::CalibrationProgress& p) {
          py::gil_scoped_acquire gil;
          try {
            if (!check_signals()) return false;
            if (progress.is_none()) return true;
            const py::object answer = progress(progress_dict(p, *calibration));
            return answer.ptr() != Py_False;  // an explicit False stops the calibration
          } catch (py::error_already_set& e) {
            pending.emplace(std::move(e));
            return false;
          }
        },
        [&] {
          py::gil_scoped_acquire gil;
          return check_signals();
        });
  }
  const CalibrationContext& context = calibration->context();
  py::dict raw;
  raw["notes"] = notes.str();
  raw["header"] = calibration->header_line();
  raw["calibration_json"] = calibration_json(context, r).dump(2) + "\n";
  raw["calibration_curve_csv"] = calibration_curve_csv(context, r);
  raw["table"] = calibration_table(context, r);
  raw["calibrated_case_yaml"] = r.parameters.size() == static_cast<Eigen::Index>(params.size())
                                    ? py::object(py::str(calibration->case_yaml(r.parameters)))
                                    : py::object(py::none());
  return py::make_tuple(raw, pending ? pending->value() : py::object(py::none()));
}

}  // namespace

void bind_calibrate(py::module_& m) {
  m.def(
      "calibrate_file",
      [](const CaseHandle& c, const std::string& file, const std::string& x, const std::string& y,
         const std::vector<std::string>& params, const std::string& algorithm, int max_evaluations,
         double xtol, int threads, int jobs, bool warm_start, const py::object& progress) {
        return calibrate_case(c, DataSource{file, x, y, "", {}, {}}, params, algorithm,
                              max_evaluations, xtol, threads, jobs, warm_start, progress);
      },
      py::arg("case"), py::arg("file"), py::arg("x"), py::arg("y"), py::arg("params"),
      py::arg("algorithm"), py::arg("max_evaluations"), py::arg("xtol"), py::arg("threads"),
      py::arg("jobs"), py::arg("warm_start"), py::arg("progress"),
      "A calibration against a CSV file: (raw result dict, exception that stopped it or None)");
  m.def(
      "calibrate_arrays",
      [](const CaseHandle& c, const std::string& label, const std::vector<double>& travel,
         const std::vector<double>& force, const std::vector<std::string>& params,
         const std::string& algorithm, int max_evaluations, double xtol, int threads, int jobs,
         bool warm_start, const py::object& progress) {
        return calibrate_case(c, DataSource{"", "", "", label, travel, force}, params, algorithm,
                              max_evaluations, xtol, threads, jobs, warm_start, progress);
      },
      py::arg("case"), py::arg("label"), py::arg("travel"), py::arg("force"), py::arg("params"),
      py::arg("algorithm"), py::arg("max_evaluations"), py::arg("xtol"), py::arg("threads"),
      py::arg("jobs"), py::arg("warm_start"), py::arg("progress"),
      "A calibration against arrays (travel in mm, force in N): as calibrate_file");
}

}  // namespace si::py
