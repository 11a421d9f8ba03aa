#include "app/fit_command.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "core/decimal_number.hpp"
#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/value_excerpt.hpp"
#include "fitting/builtin_models.hpp"
#include "fitting/linear_fit.hpp"
#include "fitting/nlopt_status.hpp"
#include "fitting/polynomial_degree.hpp"
#include "io/csv_table.hpp"

namespace si {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxAutoDegree =
    10;  // beyond this monomial fits are too ill-conditioned to mean much

Where option(const std::string& name, const std::string& value) {
  return Where{"command line", name, value, 0};
}

struct Range {
  double lo = -kInf;
  double hi = kInf;
};

double parse_bound(const std::string& part, const std::string& text) {
  if (part.empty()) return kInf;  // the caller flips the sign for an open lower end
  // Finite decimals only (core/decimal_number.hpp): nan, inf and hexadecimal floats refused.
  const std::optional<double> v = parse_decimal(part);
  if (!v)
    throw_input(
        "'" + value_excerpt(part) + "' is not a finite decimal number; expected a:b, a: or :b",
        option("--range", text));
  return *v;
}

Range parse_range(const std::string& text) {
  Range r;
  if (text.empty()) return r;
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw_input("expected a:b, a: or :b (e.g. 0.1:10)", option("--range", text));
  const std::string a = text.substr(0, colon);
  const std::string b = text.substr(colon + 1);
  r.lo = a.empty() ? -kInf : parse_bound(a, text);
  r.hi = parse_bound(b, text);
  if (r.lo > r.hi) throw_input("the lower end exceeds the upper end", option("--range", text));
  return r;
}

std::string num(double v, const char* format = "%.6g") {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

struct Points {
  Eigen::VectorXd x, y;
  int excluded = 0;  // points dropped by a model's domain (power-log: x or y not positive)
};

Points select_points(const CsvTable& t, const FitCommandOptions& o, const Range& r) {
  const std::vector<double> xs = t.numeric_column(o.x_column);
  const std::vector<double> ys = t.numeric_column(o.y_column);
  if (xs.empty()) throw_input("the file has a header but no data rows", Where{t.file, "", "", 0});
  std::vector<double> px, py;
  for (size_t i = 0; i < xs.size(); ++i)
    if (xs[i] >= r.lo && xs[i] <= r.hi) {
      px.push_back(xs[i]);
      py.push_back(ys[i]);
    }
  if (px.empty()) {
    const auto [mn, mx] = std::minmax_element(xs.begin(), xs.end());
    throw_input("no points with " + o.x_column + " in the range (the data span [" + num(*mn) +
                    ", " + num(*mx) + "])",
                option("--range", o.range));
  }
  Points p;
  p.x = Eigen::Map<Eigen::VectorXd>(px.data(), static_cast<Eigen::Index>(px.size()));
  p.y = Eigen::Map<Eigen::VectorXd>(py.data(), static_cast<Eigen::Index>(py.size()));
  return p;
}

// Log space needs x > 0 and y > 0: other points (e.g. the origin of a force-depth path) are
// dropped and counted.
Points positive_points(const Points& in) {
  std::vector<double> px, py;
  for (Eigen::Index i = 0; i < in.x.size(); ++i)
    if (in.x[i] > 0.0 && in.y[i] > 0.0) {
      px.push_back(in.x[i]);
      py.push_back(in.y[i]);
    }
  Points p;
  p.x = Eigen::Map<Eigen::VectorXd>(px.data(), static_cast<Eigen::Index>(px.size()));
  p.y = Eigen::Map<Eigen::VectorXd>(py.data(), static_cast<Eigen::Index>(py.size()));
  p.excluded = static_cast<int>(in.x.size() - p.x.size());
  return p;
}

struct Outcome {
  fit::FitResult result;
  std::string formula;
  std::optional<fit::DegreeSelection> selection;
  int excluded = 0;
};

std::string polynomial_formula(int degree) {
  std::string f = "y = a0";
  for (int k = 1; k <= degree; ++k)
    f += " + a" + std::to_string(k) + (k == 1 ? " x" : " x^" + std::to_string(k));
  return f;
}

int parse_degree(const std::string& text) {
  size_t used = 0;
  int d = -1;
  try {
    d = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || d < 0)
    throw_input("expected a degree >= 0 or 'auto'", option("--degree", text));
  return d;
}

Outcome fit_polynomial_command(const FitCommandOptions& o, const Points& p) {
  Outcome out;
  int degree = 0;
  if (o.degree.empty() || o.degree == "auto") {
    if (o.criterion != "loo" && o.criterion != "aic" && o.criterion != "aicc")
      throw_input("expected loo (leave-one-out), aic or aicc", option("--criterion", o.criterion));
    if (p.x.size() < 2)
      throw_input("degree selection needs at least 2 points", option("--degree", "auto"));
    out.selection =
        fit::select_polynomial_degree(p.x, p.y, kMaxAutoDegree,
                                      o.criterion == "aic"    ? fit::DegreeCriterion::kAic
                                      : o.criterion == "aicc" ? fit::DegreeCriterion::kAicc
                                                              : fit::DegreeCriterion::kLeaveOneOut);
    degree = out.selection->chosen_degree;
  } else {
    degree = parse_degree(o.degree);
  }
  out.result = fit::fit_polynomial(p.x, p.y, degree);
  out.formula = polynomial_formula(degree);
  return out;
}

Outcome run_model(const FitCommandOptions& o, const Points& p) {
  if (o.model != "poly" && !o.degree.empty())
    throw_input("--degree applies to --model poly only", option("--degree", o.degree));
  if (o.model == "poly") return fit_polynomial_command(o, p);
  Outcome out;
  if (o.model == "power-log") {
    const Points q = positive_points(p);
    if (q.x.size() < 2)
      throw_input("the log-space power law needs at least 2 points with x > 0 and y > 0",
                  option("--model", o.model));
    out.result = fit::fit_power_law_log(q.x, q.y);
    out.formula = "ln y = ln C1 + C2 ln x   (y = C1 * x^C2)";
    out.excluded = q.excluded;
    return out;
  }
  const fit::CurveModel model = o.model == "power"   ? fit::power_law()
                                : o.model == "hertz" ? fit::hertz_law()
                                                     : fit::power_law_with_offset();
  out.result = fit::fit_curve(model, p.x, p.y);
  out.formula = model.formula;
  return out;
}

void print_table(const FitCommandOptions& o, const Points& p, const Outcome& oc,
                 std::ostream& out) {
  const fit::FitResult& r = oc.result;
  out << "Fit of " << o.y_column << " against " << o.x_column << " in " << o.data_file << ": model "
      << o.model << ", " << oc.formula << "\n"
      << "  " << r.num_points << " points, " << o.x_column << " in [" << num(p.x.minCoeff()) << ", "
      << num(p.x.maxCoeff()) << "]";
  if (oc.excluded > 0)
    out << " (" << oc.excluded << " point(s) with x <= 0 or y <= 0 left out in log space)";
  out << "\n  status: " << fit::to_string(r.status) << " - " << r.reason << "\n";
  if (oc.selection) {
    out << "\n  degree selection by " << fit::to_string(oc.selection->criterion)
        << " (chosen: " << oc.selection->chosen_degree << ")\n"
        << "  degree            SSE     LOOCV RMSE            AIC           AICc\n";
    for (const auto& s : oc.selection->scores) {
      char line[160];
      std::snprintf(line, sizeof line, "  %6d %14.6g %14.6g %14.6g %14.6g%s\n", s.degree, s.sse,
                    s.loocv_rmse, s.aic, s.aicc,
                    s.degree == oc.selection->chosen_degree ? "  <-" : "");
      out << line;
    }
  }
  const int pct = static_cast<int>(std::lround(100 * r.confidence));
  out << "\n  parameter            value      std error    " << pct << "% CI low   " << pct
      << "% CI high\n";
  for (size_t j = 0; j < r.names.size(); ++j) {
    char line[200];
    std::snprintf(line, sizeof line, "  %-9s %14s %14s %14s %14s\n", r.names[j].c_str(),
                  num(r.parameters[j], "%.8g").c_str(), num(r.std_errors[j], "%.4g").c_str(),
                  num(r.ci_lower[j]).c_str(), num(r.ci_upper[j]).c_str());
    out << line;
  }
  out << "\n  R^2 = " << num(r.r_squared, "%.8g") << "   Pearson r = " << num(r.pearson_r, "%.8g")
      << "   RMSE = " << num(r.rmse) << "   residual std dev = " << num(r.residual_std_dev) << " ("
      << r.dof << " dof)\n";
  if (o.model == "power-log") out << "  (residuals, RMSE and R^2 of ln y)\n";
  if (r.interpolation)
    out << "  WARNING: interpolation, not a fit: " << r.names.size() << " parameters through "
        << r.num_points << " points leave no degrees of freedom; standard errors and intervals "
        << "are undefined and R^2 says nothing\n";
  out.flush();
}

nlohmann::json nullable(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json vector_json(const Eigen::VectorXd& v) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(nullable(v[i]));
  return a;
}

nlohmann::json to_json(const FitCommandOptions& o, const Points& p, const Outcome& oc) {
  const fit::FitResult& r = oc.result;
  nlohmann::json params = nlohmann::json::array();
  for (size_t j = 0; j < r.names.size(); ++j)
    params.push_back({{"name", r.names[j]},
                      {"value", nullable(r.parameters[j])},
                      {"std_error", nullable(r.std_errors[j])},
                      {"ci_low", nullable(r.ci_lower[j])},
                      {"ci_high", nullable(r.ci_upper[j])},
                      {"at_bound", r.at_bound.empty() ? false : static_cast<bool>(r.at_bound[j])}});
  nlohmann::json j = {{"data", o.data_file},
                      {"x", o.x_column},
                      {"y", o.y_column},
                      {"range", o.range},
                      {"model", o.model},
                      {"formula", oc.formula},
                      {"status", fit::to_string(r.status)},
                      {"reason", r.reason},
                      {"method", r.method},
                      {"confidence", r.confidence},
                      {"parameters", params},
                      {"covariance", nlohmann::json::array()},
                      {"statistics",
                       {{"points", r.num_points},
                        {"dof", r.dof},
                        {"sse", nullable(r.sse)},
                        {"rmse", nullable(r.rmse)},
                        {"residual_std_dev", nullable(r.residual_std_dev)},
                        {"r_squared", nullable(r.r_squared)},
                        {"pearson_r", nullable(r.pearson_r)},
                        {"log_space", o.model == "power-log"}}},
                      {"interpolation", r.interpolation},
                      {"rank_deficient", r.rank_deficient},
                      {"excluded_points", oc.excluded},
                      {"evaluations",
                       {{"residuals", r.evaluations.residuals},
                        {"jacobians", r.evaluations.jacobians},
                        {"finite_differences", r.evaluations.finite_differences}}},
                      {"points", {{"x", vector_json(p.x)}, {"y", vector_json(p.y)}}},
                      {"fitted", vector_json(r.fitted)},
                      {"residuals", vector_json(r.residuals)}};
  for (Eigen::Index i = 0; i < r.covariance.rows(); ++i)
    j["covariance"].push_back(vector_json(r.covariance.row(i).transpose()));
  if (r.nlopt_code != 0)  // nonlinear fits: what NLopt did before the polish (docs/fitting.md)
    j["nlopt"] = {{"algorithm", r.nlopt_algorithm},
                  {"code", r.nlopt_code},
                  {"status", fit::nlopt_code_name(r.nlopt_code)},
                  {"fallback", r.nlopt_fallback},
                  {"sse", nullable(r.nlopt_sse)}};
  if (oc.selection) {
    nlohmann::json scores = nlohmann::json::array();
    for (const auto& s : oc.selection->scores)
      scores.push_back({{"degree", s.degree},
                        {"sse", nullable(s.sse)},
                        {"loocv_rmse", nullable(s.loocv_rmse)},
                        {"aic", nullable(s.aic)},
                        {"aicc", nullable(s.aicc)}});
    j["degree_selection"] = {{"criterion", fit::to_string(oc.selection->criterion)},
                             {"chosen", oc.selection->chosen_degree},
                             {"scores", scores}};
  }
  return j;
}

std::string default_json_path(const FitCommandOptions& o) {
  const std::filesystem::path data(o.data_file);
  return (data.parent_path() / (data.stem().string() + ".fit-" + o.model + ".json")).string();
}

}  // namespace

std::vector<std::string> fit_model_names() {
  return {"power", "power-log", "hertz", "power-offset", "poly"};
}

int run_fit_command(const FitCommandOptions& o, std::ostream& out, std::ostream& err) {
  const auto models = fit_model_names();
  if (std::find(models.begin(), models.end(), o.model) == models.end()) {
    std::string list;
    for (const auto& m : models) list += (list.empty() ? "" : ", ") + m;
    throw_input("unknown model" + did_you_mean(o.model, models) + "; the models are: " + list,
                option("--model", o.model));
  }
  const Range range = parse_range(o.range);
  const CsvTable table = read_csv_table(o.data_file);
  const Points points = select_points(table, o, range);
  Outcome outcome;
  try {
    outcome = run_model(o, points);
  } catch (const std::invalid_argument& e) {
    // The fitting library's argument errors are about the data: say which.
    throw_input(e.what(), Where{o.data_file, o.y_column + "(" + o.x_column + ")", "", 0});
  }
  print_table(o, points, outcome, out);
  const std::string json_path = o.json_path.empty() ? default_json_path(o) : o.json_path;
  write_file_atomically(json_path, to_json(o, points, outcome).dump(2) + "\n");
  err << "wrote " << json_path << "\n";
  if (outcome.result.status == fit::FitStatus::kConverged) return 0;
  err << "shellindent: error: the fit did not converge: " << outcome.result.reason << "\n";
  return 1;
}

}  // namespace si
