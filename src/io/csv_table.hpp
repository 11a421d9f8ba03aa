// A CSV file with a header line, read into named columns. Cells are kept as text and converted
// when a column is asked for, so a file may carry text columns that are never used (a status,
// a label). Comma-separated; fields may be double-quoted ("" inside quotes is a quote); blank
// lines and lines starting with '#' are skipped; CRLF line ends are accepted.
//
// Every error is an input si::Error naming the file, the line and the column, e.g.
//   "data.csv:7: force_N = 'n/a': not a number (column 2)".
#pragma once

#include <string>
#include <vector>

namespace si {

struct CsvTable {
  std::string file;
  std::vector<std::string> names;              // from the header, in file order
  std::vector<std::vector<std::string>> rows;  // rows[i][j]: row i, column j (trimmed text)
  std::vector<int> lines;                      // 1-based line of each row in the file
  int header_line = 0;

  // Throws an input error listing the available columns (with a did-you-mean) if absent.
  int column_index(const std::string& name) const;
  // The column as numbers; an empty, non-numeric or non-finite cell is an input error.
  std::vector<double> numeric_column(const std::string& name) const;
};

// Throws an input error if the file cannot be read, has no header, repeats a column name, or a
// row has a different number of fields than the header.
CsvTable read_csv_table(const std::string& path);

}  // namespace si
