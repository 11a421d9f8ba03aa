#include "fitting/identifiability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace si::fit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The parameters carrying 95 % of the squared length of a unit vector, largest first (at least 2:
// a dependency involves two parameters or more).
std::vector<int> main_components(const Eigen::VectorXd& v) {
  std::vector<int> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return std::abs(v[a]) > std::abs(v[b]); });
  std::vector<int> out;
  double carried = 0.0;
  for (int j : order) {
    if (carried >= 0.95 * v.squaredNorm() && out.size() >= 2) break;
    out.push_back(j);
    carried += v[j] * v[j];
  }
  return out;
}

std::string number(const char* format, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string list(const std::vector<int>& parameters, const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    out += k == 0 ? "" : (k + 1 == parameters.size() ? " and " : ", ");
    out += names[parameters[k]];
  }
  return out;
}

}  // namespace

const char* to_string(IdentifiabilityIssue issue) {
  switch (issue) {
    case IdentifiabilityIssue::kInsensitive:
      return "insensitive";
    case IdentifiabilityIssue::kIllConditioned:
      return "ill_conditioned";
    case IdentifiabilityIssue::kCorrelated:
      return "correlated";
    case IdentifiabilityIssue::kNullDirection:
      return "null_direction";
  }
  return "?";
}

IdentifiabilityReport assess_identifiability(const Eigen::MatrixXd& jac,
                                             const Eigen::MatrixXd& correlation,
                                             const IdentifiabilityLimits& limits) {
  IdentifiabilityReport out;
  const auto p = static_cast<int>(jac.cols());
  Eigen::MatrixXd scaled = jac;
  std::vector<int> live;
  for (int j = 0; j < p; ++j) {
    const double norm = jac.col(j).norm();
    if (norm > 0.0 && std::isfinite(norm)) {
      scaled.col(j) /= norm;
      live.push_back(j);
    } else {
      scaled.col(j).setZero();
      out.warnings.push_back({IdentifiabilityIssue::kInsensitive, {j}, norm, {}});
    }
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeFullV);
  out.singular_values = svd.singularValues();
  out.singular_vectors = svd.matrixV();
  const double smax = out.singular_values.size() ? out.singular_values[0] : 0.0;
  const double smin = out.singular_values.size() ? out.singular_values[p - 1] : 0.0;
  out.condition_number = smin > 0.0 ? (smax / smin) * (smax / smin) : kInf;

  // Weak directions: condition index sigma_max / sigma_k above sqrt(limit). Insensitive
  // parameters are reported on their own, not again as a null direction.
  std::vector<int> involved;
  for (int k = 0; k < p && !live.empty(); ++k) {
    const double ratio = smax > 0.0 ? out.singular_values[k] / smax : 0.0;
    if (ratio * ratio * limits.condition >= 1.0) continue;
    const Eigen::VectorXd v = out.singular_vectors.col(k);
    double on_live = 0.0;
    for (int j : live) on_live += v[j] * v[j];
    if (on_live < 0.5) continue;  // the direction of a zero column: reported as insensitive
    IdentifiabilityWarning w{IdentifiabilityIssue::kNullDirection, main_components(v), ratio, v};
    for (int j : w.parameters)
      if (std::find(involved.begin(), involved.end(), j) == involved.end()) involved.push_back(j);
    out.warnings.push_back(w);
  }
  if (out.condition_number > limits.condition && live.size() == static_cast<std::size_t>(p)) {
    std::sort(involved.begin(), involved.end());
    out.warnings.insert(
        out.warnings.begin(),
        {IdentifiabilityIssue::kIllConditioned, involved, out.condition_number, {}});
  }
  for (int i = 0; i < correlation.rows(); ++i)
    for (int j = i + 1; j < correlation.cols(); ++j)
      if (std::abs(correlation(i, j)) > limits.correlation)  // NaN compares false
        out.warnings.push_back({IdentifiabilityIssue::kCorrelated, {i, j}, correlation(i, j), {}});
  return out;
}

std::string describe(const IdentifiabilityWarning& w, const std::vector<std::string>& names) {
  switch (w.issue) {
    case IdentifiabilityIssue::kInsensitive:
      return "the model does not depend on " + list(w.parameters, names) +
             " at the estimate (its column of the Jacobian is zero): the data cannot determine it";
    case IdentifiabilityIssue::kIllConditioned:
      return "the scaled J^T J is ill-conditioned (condition number " + number("%.3g", w.value) +
             "): the data do not separate " + list(w.parameters, names);
    case IdentifiabilityIssue::kCorrelated:
      return list(w.parameters, names) + " are correlated (r = " + number("%.4f", w.value) +
             "): the data fix a combination of them, not each";
    case IdentifiabilityIssue::kNullDirection: {
      std::string combo;
      for (int j : w.parameters)
        combo += (combo.empty() ? "" : ", ") + names[j] + " " + number("%+.3f", w.direction[j]);
      return "near-null direction of the scaled Jacobian (singular value " +
             number("%.3g", w.value) + " of the largest) along " + combo +
             ": moving these together barely changes the fit";
    }
  }
  return "";
}

}  // namespace si::fit
