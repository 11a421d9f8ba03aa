// A measured force-travel curve for `shellindent calibrate --data` (docs/calibration.md): a CSV
// file (io/csv_table.hpp) whose header gives each column's unit, as a suffix or in brackets:
//   travel_mm,force_N        travel (mm), force (kN)        travel [in], load [lbf]
// Travel is the indenter's travel after first touch (length units: mm m cm um µm in), force the
// indenter force along its travel (N kN mN lbf); both are converted to mm and N here, once.
//
// Refused, each as an input error naming the file, the line, the column and the value: a column
// without a unit or with a unit of the wrong kind, an empty or non-numeric or non-finite cell
// (NaN), a negative travel, a travel that does not increase strictly from row to row, and fewer
// points than `min_points` (the number of calibrated parameters + 2).
#pragma once

#include <string>
#include <vector>

#include "core/units.hpp"
#include "io/csv_table.hpp"

namespace si {

// A header cell split into its name and unit: "travel_mm" -> {"travel", "mm"}, "force (kN)" ->
// {"force", "kN"}, "load [lbf]" -> {"load", "lbf"}; the unit is empty when there is none. The
// suffix form takes the text after the last '_' as the unit only if it is a known unit.
struct ColumnName {
  std::string name;
  std::string unit;
};
ColumnName split_column_name(const std::string& header);

struct MeasuredCurve {
  std::string file;
  std::string x_header, y_header;  // the columns used, as in the header
  std::string x_unit, y_unit;      // their units as written
  std::vector<double> travel;      // mm
  std::vector<double> force;       // N
  std::vector<int> lines;          // the file line of each point
};

// x_column / y_column: a header cell as written ("travel_mm") or its name part ("travel"); empty:
// the first column with a length unit / with a force unit.
MeasuredCurve read_measured_curve(const std::string& path, const std::string& x_column,
                                  const std::string& y_column, int min_points);

// The same from a table already in memory (the Python module's arrays: a table named by its
// label, the cells as text, one line per row), with the same checks and messages.
MeasuredCurve measured_curve_from_table(const CsvTable& table, const std::string& x_column,
                                        const std::string& y_column, int min_points);

}  // namespace si
