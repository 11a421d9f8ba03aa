#include "io/measured_curve.hpp"

#include <cmath>

#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "io/csv_table.hpp"

namespace si {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// The factor from `unit` to the internal unit of `dim`; throws (from parse_quantity) if the unit
// is unknown or of another kind.
double unit_factor(const std::string& unit, Dimension dim) {
  return parse_quantity("1 " + unit, dim);
}

bool is_unit_of(const std::string& unit, Dimension dim) {
  if (unit.empty()) return false;
  try {
    unit_factor(unit, dim);
    return true;
  } catch (const Error&) {
    return false;
  }
}

bool is_known_unit(const std::string& unit) {
  for (Dimension d : {Dimension::kLength, Dimension::kForce, Dimension::kStress, Dimension::kEnergy,
                      Dimension::kAngle})
    if (is_unit_of(unit, d)) return true;
  return false;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// The index of the column asked for: its header as written, or its name part; by default the
// first column whose unit is of `dim`.
int find_column(const CsvTable& t, const std::string& asked, Dimension dim, const char* option) {
  if (asked.empty()) {
    for (std::size_t j = 0; j < t.names.size(); ++j)
      if (is_unit_of(split_column_name(t.names[j]).unit, dim)) return static_cast<int>(j);
    throw_input("no column with a " + dimension_name(dim) + " unit (" + join(accepted_units(dim)) +
                    ") in the header; name it with its unit, e.g. " +
                    (dim == Dimension::kLength ? "travel_mm" : "force_N") +
                    ", or choose one with " + option + "; the columns are: " + join(t.names),
                Where{t.file, "header", "", t.header_line});
  }
  std::vector<std::string> names;  // the name parts, for a suggestion
  for (std::size_t j = 0; j < t.names.size(); ++j) {
    if (t.names[j] == asked || split_column_name(t.names[j]).name == asked)
      return static_cast<int>(j);
    names.push_back(split_column_name(t.names[j]).name);
  }
  std::string hint = did_you_mean(asked, t.names);
  for (std::size_t j = 0; j < names.size() && hint.empty(); ++j)
    if (!did_you_mean(asked, {names[j]}).empty()) hint = " (did you mean '" + t.names[j] + "'?)";
  throw_input("no such column" + hint + "; the columns are: " + join(t.names),
              Where{t.file, "column", asked, t.header_line});
}

// The column's unit, checked: present and of the right kind. Returns the factor to mm or N.
double checked_factor(const CsvTable& t, int j, Dimension dim, std::string& unit) {
  const ColumnName c = split_column_name(t.names[j]);
  const Where where{t.file, "column " + std::to_string(j + 1), t.names[j], t.header_line};
  const std::string example = dim == Dimension::kLength ? "mm" : "N";
  if (c.unit.empty())
    throw_input("the column has no unit; write it as " + c.name + "_" + example + " or " + c.name +
                    " (" + example + ")",
                where);
  try {
    unit = c.unit;
    return unit_factor(c.unit, dim);
  } catch (const Error& e) {
    throw Error(ErrorKind::kInput, e.reason(), where);
  }
}

}  // namespace

ColumnName split_column_name(const std::string& header) {
  const std::string h = trim(header);
  for (const auto& [open, close] : {std::pair{'(', ')'}, std::pair{'[', ']'}}) {
    const auto a = h.rfind(open);
    if (a != std::string::npos && !h.empty() && h.back() == close)
      return {trim(h.substr(0, a)), trim(h.substr(a + 1, h.size() - a - 2))};
  }
  const auto u = h.rfind('_');
  if (u != std::string::npos && u + 1 < h.size() && is_known_unit(h.substr(u + 1)))
    return {h.substr(0, u), h.substr(u + 1)};
  return {h, ""};
}

MeasuredCurve read_measured_curve(const std::string& path, const std::string& x_column,
                                  const std::string& y_column, int min_points) {
  return measured_curve_from_table(read_csv_table(path), x_column, y_column, min_points);
}

MeasuredCurve measured_curve_from_table(const CsvTable& t, const std::string& x_column,
                                        const std::string& y_column, int min_points) {
  const std::string& path = t.file;
  MeasuredCurve m;
  m.file = path;
  const int jx = find_column(t, x_column, Dimension::kLength, "--x");
  const int jy = find_column(t, y_column, Dimension::kForce, "--y");
  const double fx = checked_factor(t, jx, Dimension::kLength, m.x_unit);
  const double fy = checked_factor(t, jy, Dimension::kForce, m.y_unit);
  m.x_header = t.names[jx];
  m.y_header = t.names[jy];
  const std::vector<double> x = t.numeric_column(m.x_header);  // refuses NaN and text, with line
  const std::vector<double> y = t.numeric_column(m.y_header);
  const std::string at = " (column " + std::to_string(jx + 1) + ")";
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Where where{path, m.x_header, t.rows[i][jx], t.lines[i]};
    if (x[i] < 0.0)
      throw_input("a negative travel: travel is measured from first touch (force 0)" + at, where);
    if (i > 0 && !(x[i] > x[i - 1]))
      throw_input("the travel must increase strictly; the previous point (line " +
                      std::to_string(t.lines[i - 1]) + ") has " + t.rows[i - 1][jx] + at,
                  where);
    m.travel.push_back(fx * x[i]);
    m.force.push_back(fy * y[i]);
    m.lines.push_back(t.lines[i]);
  }
  if (static_cast<int>(m.travel.size()) < min_points)
    throw_input(std::to_string(m.travel.size()) + " point(s); calibrating " +
                    std::to_string(min_points - 2) + " parameter(s) needs at least " +
                    std::to_string(min_points) +
                    " (one per parameter and two left over to estimate the error)",
                Where{path, m.y_header, std::to_string(m.travel.size()) + " points",
                      t.lines.empty() ? t.header_line : t.lines.back()});
  return m;
}

}  // namespace si
