// A calibration of a case's numbers against a measured force-travel curve, set up and run as
// `shellindent calibrate` does (docs/calibration.md): the parameters read from "KEY=LO:HI[:START]"
// (io/case_overrides.hpp's keys, bounds with units), every bound checked through the case-file
// reader, each evaluation a run of the case at the measured travels (io/force_travel.hpp) warm
// started from the nearest earlier one, the search and the statistics by fitting/calibration.hpp.
// Shared by the CLI (app/calibrate_command.cpp), which writes the report's files, and the Python
// module (python/bindings/calibrate.cpp), so both refuse the same input with the same text and
// find the same optimum.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "fitting/calibration.hpp"
#include "io/calibration_report.hpp"
#include "io/measured_curve.hpp"

namespace si {

// How the search runs: the command line's options (`shellindent calibrate --algorithm ...`).
struct CaseCalibrationSettings {
  std::string algorithm = "bobyqa";  // bobyqa (derivative-free) or slsqp (finite differences)
  int max_evaluations = 100;
  double xtol = 1e-4;      // the search stops when its steps are below this fraction of each range
  int threads = 1;         // assembly threads of each run (0: OpenMP's default)
  int jobs = 1;            // the Jacobian's runs at once (each with `threads` threads)
  bool warm_start = true;  // start each run from the nearest earlier one's states
};

struct CaseCalibrationInput {
  std::string case_label;           // the case file's name (or a label), as messages name it
  std::string case_text;            // its YAML
  std::vector<std::string> params;  // "material.E3=5GPa:20GPa[:10GPa]"
  CaseCalibrationSettings settings;
};

// The measured curve, read once the number of parameters is known: min_points = parameters + 2.
using MeasuredCurveReader = std::function<MeasuredCurve(int min_points)>;

class CaseCalibration {
 public:
  // Checks, in the CLI's order, the case, the parameters, the algorithm, the thread counts, the
  // evaluation budget, the data and every bound; throws an input si::Error at the first bad one.
  // Notes (a start moved into the bounds) go to `notes`.
  CaseCalibration(const CaseCalibrationInput& input, const MeasuredCurveReader& read_data,
                  std::ostream& notes);
  ~CaseCalibration();
  CaseCalibration(const CaseCalibration&) = delete;
  CaseCalibration& operator=(const CaseCalibration&) = delete;

  // The search and, at its best point, the statistics. `progress` is called after every
  // evaluation (one call at a time), `keep_going` after every converged point of a run (from
  // the Jacobian's threads too); either returning false stops: status interrupted.
  fit::CalibrationResult run(const std::function<bool(const fit::CalibrationProgress&)>& progress,
                             const std::function<bool()>& keep_going) const;

  const CalibrationContext& context() const;
  // The case with the parameters at `values` (calibrated_case.yaml at the optimum).
  std::string case_yaml(const Eigen::VectorXd& values) const;
  // "calibrate: 12 search   material.E3 = ... : S = ... (best ...), 1.6 s, warm start, ..."
  std::string progress_line(const fit::CalibrationProgress& p) const;
  // "calibrate: CASE against DATA: N points, travel A to B mm, P parameter(s), ..."
  std::string header_line() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace si
