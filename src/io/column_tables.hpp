// The path's column table (analysis/path_columns.hpp) as text for the readers outside the
// code: the table of docs/results.md and the Python module studies/result_columns.py that the
// study scripts read columns by. scripts/update_schema.sh writes both from a build;
// tests/io/test_column_tables.cpp fails if the files differ from what these render.
#pragma once

#include <string>

namespace si {

// The markdown table (header, separator, one row per column), each line ending in '\n'.
std::string path_columns_markdown();
// The begin and end markers around it in docs/results.md.
inline const char* const kColumnsBegin = "<!-- columns:begin path.csv -->";
inline const char* const kColumnsEnd = "<!-- columns:end path.csv -->";

// studies/result_columns.py: one constant per column (its name in upper case), PATH_COLUMNS in
// path.csv's order and UNITS.
std::string path_columns_python();

}  // namespace si
