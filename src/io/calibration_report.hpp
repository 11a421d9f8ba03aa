// What `shellindent calibrate` writes (docs/calibration.md): calibration.json (the optimum, its
// standard errors, intervals, ellipsoid, correlations, identifiability warnings, NLopt's status,
// the evaluation counts), calibration_curve.csv (measured and fitted force at each measured
// travel) and the table printed on stdout. Text is produced here; the caller writes it
// atomically.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/units.hpp"
#include "fitting/calibration.hpp"
#include "io/measured_curve.hpp"

namespace si {

// What the report needs besides the result: where the data and the case came from.
struct CalibrationContext {
  std::string case_file;
  MeasuredCurve data;
  std::vector<Dimension> dimensions;  // of each parameter (its values are in internal units)
  int threads = 0;
};

nlohmann::json calibration_json(const CalibrationContext& c, const fit::CalibrationResult& r);

// travel_mm, measured_force_N, fitted_force_N, residual_N (empty without statistics).
std::string calibration_curve_csv(const CalibrationContext& c, const fit::CalibrationResult& r);

// The table for stdout: status, parameters with errors and intervals, fit statistics, the
// correlation matrix and the warnings.
std::string calibration_table(const CalibrationContext& c, const fit::CalibrationResult& r);

}  // namespace si
