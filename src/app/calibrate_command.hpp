// `shellindent calibrate CASE.yaml --data MEASURED.csv --param KEY=LO:HI[:START] ... [--x COL]
// [--y COL] [--out DIR]`: adjusts numbers of a case file (io/case_overrides.hpp: elastic
// constants, ply thickness) within bounds so that the case's force-travel curve matches a
// measured one (io/measured_curve.hpp), each evaluation a full run of the case
// (io/force_travel.hpp), the search and the statistics by fitting/calibration.hpp. Prints a
// progress line per evaluation to `err` and a table to `out`; writes DIR/calibration.json,
// DIR/calibration_curve.csv and DIR/calibrated_case.yaml (the case with the optimum), each
// atomically, once the calibration has ended (an interrupted one too, with the best point so
// far). Bad input throws before anything runs or is written (exit 2); returns 0 when the search
// converged, 1 otherwise (budget exhausted, Ctrl-C, NLopt failure). docs/calibration.md.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "io/case_calibration.hpp"

namespace si {

struct CalibrateCommandOptions {
  std::string case_file;
  std::string data_file;
  std::vector<std::string> params;   // "material.E3=5GPa:20GPa[:10GPa]"
  std::string x_column, y_column;    // empty: the first length / force column
  std::string out_dir;               // empty: results/<case stem>_calibration
  CaseCalibrationSettings settings;  // --algorithm, --max-evaluations, --xtol, --threads, -j
};

int run_calibrate_command(const CalibrateCommandOptions& options, std::ostream& out,
                          std::ostream& err);

}  // namespace si
