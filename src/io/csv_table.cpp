#include "io/csv_table.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>

#include "core/decimal_number.hpp"
#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/value_excerpt.hpp"

namespace si {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// Splits one line at commas outside double quotes; quotes are removed, "" becomes ".
std::vector<std::string> split_fields(const std::string& line, const Where& where) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        field += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      fields.push_back(trim(field));
      field.clear();
    } else {
      field += ch;
    }
  }
  if (quoted) throw_input("a quoted field is not closed on this line", where);
  fields.push_back(trim(field));
  return fields;
}

bool skipped(const std::string& line) {
  const std::string t = trim(line);
  return t.empty() || t[0] == '#';
}

std::string list(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw_input("cannot open the file", Where{path, "", "", 0});
  CsvTable t;
  t.file = path;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (skipped(line)) continue;
    const Where where{path, "", "", number};
    std::vector<std::string> fields = split_fields(line, where);
    if (t.header_line == 0) {
      t.header_line = number;
      for (size_t j = 0; j < fields.size(); ++j) {
        if (fields[j].empty())
          throw_input("column " + std::to_string(j + 1) + " of the header has no name", where);
        for (size_t k = 0; k < j; ++k)
          if (fields[k] == fields[j])
            throw_input(
                "column name '" + value_excerpt(fields[j]) + "' appears twice in the header",
                where);
      }
      t.names = std::move(fields);
      continue;
    }
    if (fields.size() != t.names.size())
      throw_input("this row has " + std::to_string(fields.size()) + " fields, the header (line " +
                      std::to_string(t.header_line) + ") has " + std::to_string(t.names.size()),
                  where);
    t.rows.push_back(std::move(fields));
    t.lines.push_back(number);
  }
  if (t.header_line == 0) throw_input("no header line (the file is empty)", Where{path, "", "", 0});
  return t;
}

int CsvTable::column_index(const std::string& name) const {
  for (size_t j = 0; j < names.size(); ++j)
    if (names[j] == name) return static_cast<int>(j);
  // Column names often carry a unit suffix the user left out ("depth" for "depth_mm").
  std::string hint = did_you_mean(name, names);
  for (size_t j = 0; j < names.size() && hint.empty() && !name.empty(); ++j)
    if (names[j].rfind(name + "_", 0) == 0) hint = " (did you mean '" + names[j] + "'?)";
  throw_input("no such column" + hint + "; the columns are: " + list(names),
              Where{file, "column", name, header_line});
}

std::vector<double> CsvTable::numeric_column(const std::string& name) const {
  const int j = column_index(name);
  std::vector<double> values;
  values.reserve(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string& cell = rows[i][j];
    const Where where{file, name, cell, lines[i]};
    const std::string at = " (column " + std::to_string(j + 1) + ")";
    if (cell.empty()) throw_input("empty cell" + at, where);
    // Decimal numbers only (core/decimal_number.hpp): no nan, inf or hexadecimal floats.
    std::size_t used = 0;
    const std::optional<double> v = parse_decimal_prefix(cell, used);
    if (v && used == cell.size() && !std::isfinite(*v))
      throw_input("not a finite number" + at, where);
    if (!v || used != cell.size())
      throw_input(
          (is_hexadecimal(cell) ? "a hexadecimal number: write it in decimal" : "not a number") +
              at,
          where);
    values.push_back(*v);
  }
  return values;
}

}  // namespace si
