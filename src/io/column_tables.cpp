#include "io/column_tables.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "analysis/path_columns.hpp"

namespace si {
namespace {

std::string constant_name(const std::string& column) {
  std::string s = column;
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

}  // namespace

std::string path_columns_markdown() {
  std::ostringstream os;
  os << "| column | unit | meaning |\n|---|---|---|\n";
  for (const ColumnSpec& c : path_columns())
    os << "| `" << c.name << "` | " << c.unit << " | " << c.description << " |\n";
  return os.str();
}

std::string path_columns_python() {
  std::ostringstream os;
  os << "\"\"\"The result columns of path.csv, path.json and path_grid.csv (docs/results.md),\n"
        "generated from src/analysis/path_columns.cpp by scripts/update_schema.sh: do not edit.\n"
        "tests/io/test_column_tables.cpp fails if this file and the table differ. The study\n"
        "scripts read columns by these names.\n\"\"\"\n\n";
  for (const ColumnSpec& c : path_columns())
    os << constant_name(c.name) << " = \"" << c.name << "\"\n";
  os << "\n# All columns, in path.csv's order.\nPATH_COLUMNS = (\n";
  for (const ColumnSpec& c : path_columns()) os << "    " << constant_name(c.name) << ",\n";
  os << ")\n\nUNITS = {\n";
  for (const ColumnSpec& c : path_columns())
    os << "    " << constant_name(c.name) << ": \"" << c.unit << "\",\n";
  os << "}\n";
  return os.str();
}

}  // namespace si
