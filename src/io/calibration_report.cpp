#include "io/calibration_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/path_columns.hpp"
#include "fitting/nlopt_status.hpp"

namespace si {
namespace {

using nlohmann::json;

json nullable(double v) {
  return std::isfinite(v) ? json(v) : json();
}

json vector_json(const Eigen::VectorXd& v) {
  json a = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(nullable(v[i]));
  return a;
}

json matrix_json(const Eigen::MatrixXd& m) {
  json a = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) a.push_back(vector_json(m.row(i).transpose()));
  return a;
}

// Element j of v, NaN if v is shorter (no statistics).
double at(const Eigen::VectorXd& v, Eigen::Index j) {
  return j < v.size() ? v[j] : std::nan("");
}

std::string unit_of(Dimension d) {
  return d == Dimension::kDimensionless ? "" : internal_unit(d);
}

json parameters_json(const CalibrationContext& c, const fit::CalibrationResult& r) {
  json out = json::array();
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    const auto k = static_cast<Eigen::Index>(j);
    out.push_back({{"key", r.names[j]},
                   {"unit", unit_of(c.dimensions[j])},
                   {"value", nullable(at(r.parameters, k))},
                   {"start", r.start[k]},
                   {"std_error", nullable(at(r.std_errors, k))},
                   {"ci_low", nullable(at(r.ci_lower, k))},
                   {"ci_high", nullable(at(r.ci_upper, k))},
                   {"at_bound", j < r.at_bound.size() && r.at_bound[j]},
                   {"jacobian_step", nullable(at(r.jacobian_steps, k))}});
  }
  return out;
}

json identifiability_json(const fit::CalibrationResult& r) {
  json warnings = json::array();
  for (const auto& w : r.identifiability.warnings) {
    json names = json::array();
    for (int j : w.parameters) names.push_back(r.names[j]);
    warnings.push_back({{"issue", fit::to_string(w.issue)},
                        {"parameters", names},
                        {"value", nullable(w.value)},
                        {"direction", vector_json(w.direction)},
                        {"message", fit::describe(w, r.names)}});
  }
  return {{"condition_number_scaled_JtJ", nullable(r.identifiability.condition_number)},
          {"singular_values_scaled_J", vector_json(r.identifiability.singular_values)},
          {"singular_vectors_scaled_J", matrix_json(r.identifiability.singular_vectors)},
          {"warnings", warnings}};
}

json ellipsoid_json(const fit::CalibrationResult& r) {
  if (r.ellipsoid.shape.size() == 0) return json();
  return {{"confidence", r.ellipsoid.confidence},
          {"f_quantile", r.ellipsoid.f_quantile},
          {"definition", "(c - c_opt)^T shape^-1 (c - c_opt) <= 1, shape = p F covariance"},
          {"shape", matrix_json(r.ellipsoid.shape)},
          {"half_lengths", vector_json(r.ellipsoid.half_lengths)},
          {"axes", matrix_json(r.ellipsoid.axes)},
          {"shadow_half_widths", vector_json(r.ellipsoid.shadow_half_widths)}};
}

std::string number(double v, const char* format = "%.6g") {
  if (!std::isfinite(v)) return "-";
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

json calibration_json(const CalibrationContext& c, const fit::CalibrationResult& r) {
  return {{"case", c.case_file},
          {"data",
           {{"file", c.data.file},
            {"travel_column", c.data.x_header},
            {"force_column", c.data.y_header},
            {"points", c.data.travel.size()},
            {"note",
             std::string("travel = indenter travel after first touch (path.csv's ") +
                 column_name(PathColumn::kDepth) +
                 "; with contact.local it includes the local indentation), converted to mm; force "
                 "in N, whole shell"}}},
          {"status", fit::to_string(r.status)},
          {"reason", r.reason},
          {"nlopt",
           {{"algorithm", r.algorithm},
            {"code", r.nlopt_code},
            {"status", r.nlopt_code == 0 ? "not run" : fit::nlopt_code_name(r.nlopt_code)}}},
          {"parameters", parameters_json(c, r)},
          {"confidence", r.confidence},
          {"statistics",
           {{"available", r.statistics_available},
            {"points", r.num_points},
            {"dof", r.dof},
            {"sse_N2", nullable(r.sse)},
            {"sse_start_N2", nullable(r.sse_start)},
            {"rmse_N", nullable(r.rmse)},
            {"residual_std_dev_N", nullable(r.residual_std_dev)},
            {"gauss_newton_step", vector_json(r.gauss_newton_step)},
            {"distance_to_optimum_in_std_errors", nullable(r.distance_to_optimum)}}},
          {"covariance", matrix_json(r.covariance)},
          {"correlation", matrix_json(r.correlation)},
          {"confidence_region", ellipsoid_json(r)},
          {"identifiability", identifiability_json(r)},
          {"jacobian_N_per_unit", matrix_json(r.jacobian)},
          {"evaluations",
           {{"search", r.evaluations.search},
            {"jacobian", r.evaluations.jacobian},
            {"failed", r.evaluations.failed},
            {"total", r.evaluations.total()}}},
          {"threads", c.threads},
          {"seconds", r.seconds}};
}

std::string calibration_curve_csv(const CalibrationContext& c, const fit::CalibrationResult& r) {
  std::ostringstream os;
  os.precision(12);
  os << "travel_mm,measured_force_N,fitted_force_N,residual_N\n";
  for (std::size_t i = 0; i < c.data.travel.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    os << c.data.travel[i] << ',' << c.data.force[i] << ',';
    if (k < r.predicted.size())
      os << r.predicted[k] << ',' << r.residuals[k];
    else
      os << ',';
    os << '\n';
  }
  return os.str();
}

std::string calibration_table(const CalibrationContext& c, const fit::CalibrationResult& r) {
  std::ostringstream os;
  os << "Calibration of " << c.case_file << " against " << c.data.file << " ("
     << c.data.travel.size() << " points, travel " << number(c.data.travel.front()) << " to "
     << number(c.data.travel.back()) << " mm): " << fit::to_string(r.status) << "\n"
     << "  " << r.reason << "; " << r.evaluations.search << " search + " << r.evaluations.jacobian
     << " Jacobian evaluations (" << r.evaluations.failed << " failed), "
     << number(r.seconds, "%.1f") << " s\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-26s %14s %12s %29s %14s\n", "parameter", "value",
                "std. error", "95% interval", "start");
  os << line;
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    const auto k = static_cast<Eigen::Index>(j);
    const std::string unit = unit_of(c.dimensions[j]);
    const std::string interval =
        "[" + number(at(r.ci_lower, k)) + ", " + number(at(r.ci_upper, k)) + "]";
    std::snprintf(line, sizeof line, "%-26s %14s %12s %29s %14s %s%s\n", r.names[j].c_str(),
                  number(at(r.parameters, k)).c_str(), number(at(r.std_errors, k)).c_str(),
                  interval.c_str(), number(r.start[k]).c_str(), unit.c_str(),
                  j < r.at_bound.size() && r.at_bound[j] ? "  (at a bound)" : "");
    os << line;
  }
  if (r.statistics_available) {
    os << "RMSE " << number(r.rmse) << " N, residual standard deviation "
       << number(r.residual_std_dev) << " N (" << r.dof << " degrees of freedom), S "
       << number(r.sse) << " N^2 (start " << number(r.sse_start) << ")\n";
    if (r.names.size() > 1) {
      os << "correlation:\n";
      for (Eigen::Index i = 0; i < r.correlation.rows(); ++i) {
        os << "  ";
        for (Eigen::Index j = 0; j < r.correlation.cols(); ++j)
          os << (j ? " " : "") << number(r.correlation(i, j), "%+8.4f");
        os << "\n";
      }
    }
    os << "the search stopped " << number(r.distance_to_optimum, "%.2g")
       << " standard errors from the optimum of the linearised problem (Gauss-Newton step)\n";
    os << "condition number of the scaled J^T J: "
       << number(r.identifiability.condition_number, "%.3g") << "\n";
  }
  for (const auto& w : r.identifiability.warnings)
    os << "WARNING: identifiability: " << fit::describe(w, r.names) << "\n";
  return os.str();
}

}  // namespace si
