// `shellindent fit DATA.csv --model MODEL --x COL --y COL [--degree N|auto] [--range a:b]
// [--json out.json]`: fits a curve to two columns of a CSV file with the generic fitting library
// (fitting/, docs/fitting.md), prints a table of the parameters (value, standard error, 95 %
// interval) and the goodness of fit, and writes everything, residuals included, as JSON
// (default: DATA.fit-MODEL.json beside the CSV).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace si {

struct FitCommandOptions {
  std::string data_file;
  std::string model;  // power, power-log, hertz, power-offset, poly
  std::string x_column, y_column;
  std::string degree;             // poly only: a number or "auto" (default "auto")
  std::string criterion = "loo";  // --degree auto: "loo" (leave-one-out) or "aic"
  std::string range;              // "a:b", "a:" or ":b" on x; empty: all points
  std::string json_path;          // empty: DATA.fit-MODEL.json beside the CSV
};

// The model names the command knows, in the order of its help.
std::vector<std::string> fit_model_names();

// Returns 0 if the fit converged, 1 if it stalled or failed (the table and JSON are still
// written); throws an input si::Error for bad options or data.
int run_fit_command(const FitCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace si
