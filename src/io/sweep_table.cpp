#include "io/sweep_table.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "analysis/path_columns.hpp"
#include "fitting/builtin_models.hpp"
#include "fitting/curve_model.hpp"
#include "io/critical_points_json.hpp"
#include "io/csv_table.hpp"
#include "io/damage_summary.hpp"
#include "io/path_results.hpp"
#include "io/source_fingerprint.hpp"

namespace si {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The path columns the summary reads (analysis/path_columns.hpp).
const char* depth_column() {
  return column_name(PathColumn::kDepth);
}

const char* force_column() {
  return column_name(PathColumn::kForce);
}

// Linear interpolation of column `y` at depth `d` on the first passage; NaN if not reached.
double value_at_depth(const json& points, const char* y, double d) {
  for (size_t i = 0; i < points.size(); ++i) {
    const double d0 = points[i][depth_column()];
    if (std::abs(d0 - d) <= 1e-9 * (1 + d)) return points[i][y];
    if (i + 1 < points.size()) {
      const double d1 = points[i + 1][depth_column()];
      if ((d - d0) * (d - d1) < 0) {
        const double t = (d - d0) / (d1 - d0);
        return (1 - t) * points[i][y].get<double>() + t * points[i + 1][y].get<double>();
      }
    }
  }
  return kNaN;
}

// The first inflection of T_N against the column `against` (k11): {depth, force} or NaNs.
std::pair<double, double> first_inflection(const json& events, PathColumn against) {
  const std::string inflection = cont::event_type_name(cont::EventType::kInflection);
  for (const json& e : events)
    if (e.value("type", "") == inflection && e.value("monitor", "") == force_column() &&
        e.value("against", "") == column_name(against))
      return {e.value(depth_column(), kNaN), e.value(force_column(), kNaN)};
  return {kNaN, kNaN};
}

// The case's path_grid.csv (pseudo-arclength runs: the force at the depth grid, interpolated on
// the branch by cubic Hermite, io/path_results.hpp) as points {depth_mm, force_N}; empty when
// the run wrote none (its points are then on the grid already).
json grid_points(const fs::path& dir) {
  json points = json::array();
  const fs::path file = dir / "path_grid.csv";
  if (!fs::exists(file)) return points;
  const CsvTable grid = read_csv_table(file.string());
  const std::vector<double> depth = grid.numeric_column(depth_column());
  const std::vector<double> force = grid.numeric_column(force_column());
  for (std::size_t i = 0; i < depth.size(); ++i)
    points.push_back({{depth_column(), depth[i]}, {force_column(), force[i]}});
  return points;
}

// T = C1 h^C2 by least squares in linear space over the study's depth range (fitting library),
// on the case's depth grid dh, 2 dh, ... (the paper's 0.1 mm stepping, P9): path_grid.csv's
// values where the points are adaptive (grid_points), read off `points` otherwise. Why the grid:
// adaptive points crowd where the step controller shrank the step (contact changes), which weights
// the fit towards those depths; on the [0/0]2S cap C2 moved from 1.61 (grid) to 1.79 (points).
void fit_contact_law(const json& points, const StudyFit& f, double dh, json& row) {
  std::vector<double> h, t;
  const double end = points.back()[depth_column()];
  for (long k = 1;; ++k) {
    const double d = static_cast<double>(k) * dh;
    if (d > f.depth_max * (1 + 1e-12) || d > end * (1 + 1e-12)) break;
    if (d <= f.depth_min) continue;
    const double force = value_at_depth(points, force_column(), d);
    if (!std::isfinite(force)) continue;
    h.push_back(d);
    t.push_back(force);
  }
  if (h.size() < 3) {
    row["fit_status"] = "too few points (" + std::to_string(h.size()) + ") in the fit range";
    return;
  }
  const Eigen::VectorXd x = Eigen::Map<Eigen::VectorXd>(h.data(), Eigen::Index(h.size()));
  const Eigen::VectorXd y = Eigen::Map<Eigen::VectorXd>(t.data(), Eigen::Index(t.size()));
  const fit::FitResult r = fit::fit_curve(fit::power_law(), x, y);
  row["fit_status"] = fit::to_string(r.status);
  row["C1"] = r.parameters[0];
  row["C1_lo"] = r.ci_lower[0];
  row["C1_hi"] = r.ci_upper[0];
  row["C2"] = r.parameters[1];
  row["C2_lo"] = r.ci_lower[1];
  row["C2_hi"] = r.ci_upper[1];
  row["R2"] = r.r_squared;
}

// A CSV cell: numbers with 10 significant digits (NaN and absent: empty), text quoted if needed.
std::string cell(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number()) {
    const double d = v.get<double>();
    if (!std::isfinite(d)) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", d);
    return buf;
  }
  const std::string s = v.is_string() ? v.get<std::string>() : v.dump();
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

}  // namespace

std::optional<json> read_json_file(const fs::path& p) {
  if (!fs::is_regular_file(p)) return std::nullopt;
  try {
    return json::parse(read_text(p));
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

bool finished_status(const std::string& status) {
  return status == run_status_name(RunStatus::kCompleted) ||
         status == run_status_name(RunStatus::kReachedBound);
}

CaseState case_state(const fs::path& dir, const std::string& yaml) {
  if (!fs::is_regular_file(dir / "case.yaml") || read_text(dir / "case.yaml") != yaml)
    return CaseState::kToRun;
  const std::optional<json> path = read_json_file(dir / "path.json");
  if (!path || !finished_status(path->value("status", ""))) return CaseState::kToRun;
  const json build = path->value("build", json::object());
  return build.value("source_fingerprint", "") == source_fingerprint() ? CaseState::kDone
                                                                       : CaseState::kStale;
}

const char* case_state_name(CaseState state) {
  const char* const names[] = {"to_run", "done", "stale"};  // in CaseState's order
  return names[static_cast<int>(state)];
}

std::string last_log_line(const fs::path& dir) {
  std::istringstream in(read_text(dir / "run.log"));
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no output (see run.log)" : last;
}

json summarize_case(const StudyCase& c, const fs::path& dir, const StudyFile& study) {
  json row;
  row["case"] = c.index;
  for (const auto& [key, value] : c.values) row[key] = value;
  const std::optional<json> path = read_json_file(dir / "path.json");
  if (!path) {
    row["status"] = "failed";
    row["reason"] = last_log_line(dir);
    return row;
  }
  const json& pts = (*path)["points"];
  row["status"] = path->value("status", "");
  row["reason"] = path->value("reason", "");
  row["points"] = pts.size();
  if (pts.empty()) return row;
  const char* depth = depth_column();
  const char* force = force_column();
  row["depth_end_mm"] = pts.back()[depth];
  row["force_at_depth_max_N"] = value_at_depth(pts, force, c.case_file.path.depth_max);
  size_t imax = 0;
  for (size_t i = 0; i < pts.size(); ++i)
    if (pts[i][force].get<double>() > pts[imax][force].get<double>()) imax = i;
  row["max_force_N"] = pts[imax][force];
  row["depth_at_max_force_mm"] = pts[imax][depth];
  row["energy_end_Nmm"] = pts.back()[column_name(PathColumn::kEnergy)];
  const json events = (*path)["events"];
  for (const auto& [k, column] :
       {std::pair{"k11", PathColumn::kK11}, std::pair{"k22", PathColumn::kK22}}) {
    const auto [at_depth, at_force] = first_inflection(events, column);
    row[std::string("critical_") + k + "_depth_mm"] = at_depth;
    row[std::string("critical_") + k + "_force_N"] = at_force;
  }
  summarize_critical_points(*path, row);
  summarize_damage(*path, row);
  if (study.has_fit) {
    const json grid = grid_points(dir);
    fit_contact_law(grid.empty() ? pts : grid, study.fit, c.case_file.path.step, row);
  }
  return row;
}

std::vector<std::string> sweep_columns(const StudyFile& study,
                                       const std::vector<StudyCase>& cases) {
  std::vector<std::string> cols{"case"};
  for (const auto& kv : study.vary) cols.push_back(kv.first);
  for (const char* c :
       {"status", "reason", "points", "depth_end_mm", "force_at_depth_max_N", "max_force_N",
        "depth_at_max_force_mm", "energy_end_Nmm", "critical_k11_depth_mm", "critical_k11_force_N",
        "critical_k22_depth_mm", "critical_k22_force_N"})
    cols.push_back(c);
  for (const std::string& c : critical_point_columns()) cols.push_back(c);
  for (const std::string& c : damage_columns(cases)) cols.push_back(c);
  if (study.has_fit)
    for (const char* c : {"fit_status", "C1", "C1_lo", "C1_hi", "C2", "C2_lo", "C2_hi", "R2"})
      cols.push_back(c);
  return cols;
}

std::string sweep_csv(const StudyFile& study, const std::vector<StudyCase>& cases,
                      const json& rows) {
  const std::vector<std::string> cols = sweep_columns(study, cases);
  std::ostringstream os;
  for (size_t i = 0; i < cols.size(); ++i) os << (i ? "," : "") << cols[i];
  os << "\n";
  for (const json& row : rows) {
    for (size_t i = 0; i < cols.size(); ++i)
      os << (i ? "," : "") << (row.contains(cols[i]) ? cell(row[cols[i]]) : "");
    os << "\n";
  }
  return os.str();
}

std::string sweep_json(const StudyFile& study, const std::vector<StudyCase>& cases, bool quick,
                       const json& rows) {
  const json doc{{"study", study.file},
                 {"name", study.name},
                 {"base", study.base},
                 {"quick", quick},
                 {"combine", study.zip ? "zip" : "product"},
                 {"columns", sweep_columns(study, cases)},
                 {"cases", rows}};
  return doc.dump(2) + "\n";
}

}  // namespace si
