// The depth path of a case, as `shellindent run` computes it (app/run_command.cpp without the
// files): IndentationSetup, then run_indentation_path with a callback per converged point. The
// GIL is released during the solve and taken back in the callback, which calls the progress
// function and checks for signals: Ctrl-C (KeyboardInterrupt) or an exception of the progress
// function stops the run at that point, every converged point kept, and the exception is handed
// back with the result (shellindent/run.py attaches the result to it and raises it).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>

#include "analysis/companion_mesh.hpp"
#include "analysis/indentation_run.hpp"
#include "analysis/path_columns.hpp"
#include "bindings.hpp"
#include "io/case_digest.hpp"
#include "io/case_key_location.hpp"
#include "io/path_results.hpp"

namespace si::py {
namespace {

// The columns a run of this case writes (path.csv's): those of every run, the failure indices
// it monitors, the stability columns and the force's error estimate if it asks for them
// (analysis/path_columns.hpp).
std::vector<PathColumn> case_columns(const IndentationCase& spec) {
  return run_columns(spec.damage ? spec.damage->criteria : std::vector<Criterion>{},
                     spec.path.stability, spec.mesh.error_estimate == ErrorEstimate::kCompanion);
}

// A point's values by column name, for the progress function.
py::dict point_dict(const PathPoint& p, const std::vector<PathColumn>& columns) {
  py::dict d;
  const std::vector<double> values = path_point_values(p, columns);
  d["index"] = p.index;
  for (std::size_t c = 0; c < columns.size(); ++c) d[column_name(columns[c])] = values[c];
  return d;
}

// The path's columns as NumPy arrays, one value per converged point.
py::dict path_arrays(const PathResult& r) {
  const std::vector<PathColumn> columns = result_columns(r);
  std::vector<py::array_t<double>> arrays;
  for (std::size_t c = 0; c < columns.size(); ++c)
    arrays.emplace_back(static_cast<py::ssize_t>(r.points.size()));
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const std::vector<double> values = path_point_values(r.points[i], columns);
    for (std::size_t c = 0; c < columns.size(); ++c) arrays[c].mutable_at(i) = values[c];
  }
  py::dict d;
  for (std::size_t c = 0; c < columns.size(); ++c) d[column_name(columns[c])] = arrays[c];
  return d;
}

py::dict column_units() {
  py::dict d;
  for (const ColumnSpec& c : path_columns()) d[c.name] = c.unit;
  return d;
}

py::tuple run_case(const CaseHandle& c, const py::object& progress, int threads,
                   const std::string& checkpoint) {
  std::optional<IndentationSetup> setup;
  {
    py::gil_scoped_release nogil;
    try {
      setup.emplace(c.file, threads);
    } catch (const Error& e) {
      throw located_in_case(e, c.text);
    }
  }
  std::optional<py::error_already_set> pending;  // what stopped the run from Python
  const std::vector<PathColumn> columns = case_columns(setup->spec);
  const PathCallback on_point = [&](const PathPoint& p, const cont::Vector&) {
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (progress.is_none()) return true;
      const py::object answer = progress(point_dict(p, columns));
      return answer.ptr() != Py_False;  // an explicit False stops the run
    } catch (py::error_already_set& e) {
      pending.emplace(std::move(e));
      return false;
    }
  };
  PathResult r;
  {
    py::gil_scoped_release nogil;
    // The CLI's checkpoints: every 10 points, with the case's digest as the record, so that
    // `shellindent run CASE --resume` continues it (and refuses another case). The solver's
    // caches are dropped at each one (bit-for-bit resume), which changes the path's last bits:
    // with a checkpoint the module's path is the CLI's bit for bit.
    PathControl control;
    control.checkpoint = checkpoint;
    const nlohmann::json record{{"case", case_digest(c.text).to_json()},
                                {"vtu", nlohmann::json::array()}};
    control.save_record = [&] { return record; };
    r = run_indentation_path(*setup, on_point, control);
    // mesh.error_estimate: companion, as the CLI: the companion's points are not the progress
    // function's (another mesh), only Ctrl-C stops it.
    if (!pending && setup->spec.mesh.error_estimate == ErrorEstimate::kCompanion)
      run_companion(setup->spec, r, threads, {}, [&](const PathPoint&, const cont::Vector&) {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() == 0) return true;
        pending.emplace();
        return false;
      });
  }
  py::dict raw;
  raw["path"] = path_arrays(r);
  raw["units"] = column_units();
  raw["status"] = run_status_name(r.status);
  raw["reason"] = r.reason;
  raw["method"] = run_method_name(r.method);
  raw["completed"] = r.completed;
  raw["events_json"] = events_json(r).dump(2) + "\n";
  raw["path_json"] = path_json(*setup, r).dump(2) + "\n";
  raw["path_csv"] = path_csv(r);
  // As `shellindent run` writes it (pseudo-arclength runs): the sweep's fit reads it.
  raw["path_grid_csv"] =
      r.method == RunMethod::kPseudoArclength
          ? py::object(py::str(path_grid_csv(r, setup->spec.path.step, setup->spec.path.depth_max)))
          : py::object(py::none());
  raw["warnings"] = setup->model.warnings;
  return py::make_tuple(raw, pending ? pending->value() : py::object(py::none()));
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("run_case", &run_case, py::arg("case"), py::arg("progress"), py::arg("threads") = 0,
        py::arg("checkpoint") = "",
        "The path of a case: (raw result dict, exception that stopped it or None)");
  m.def("column_units", &column_units,
        "every column of the table (analysis/path_columns) and its unit, in path.csv's order; "
        "a run writes the leading ones and the optional ones it asks for");
}

}  // namespace si::py
