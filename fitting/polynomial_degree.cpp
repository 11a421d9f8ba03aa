#include "fitting/polynomial_degree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fitting/linear_fit.hpp"

namespace si::fit {

const char* to_string(DegreeCriterion criterion) {
  switch (criterion) {
    case DegreeCriterion::kAic:
      return "AIC";
    case DegreeCriterion::kAicc:
      return "AICc";
    case DegreeCriterion::kLeaveOneOut:
      return "leave-one-out";
  }
  return "leave-one-out";
}

DegreeSelection select_polynomial_degree(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                         int max_degree, DegreeCriterion criterion) {
  const auto n = static_cast<int>(x.size());
  if (n < 2 || y.size() != x.size())
    throw std::invalid_argument("degree selection needs at least 2 points (x and y alike)");
  if (max_degree < 0) throw std::invalid_argument("maximum degree must be >= 0");
  // Roundoff level of a residual: a few hundred ulps of the largest |y|.
  const double floor_rms = 256 * std::numeric_limits<double>::epsilon() * y.cwiseAbs().maxCoeff();
  const double floor_sse = std::max(n * floor_rms * floor_rms, std::numeric_limits<double>::min());

  DegreeSelection sel;
  sel.criterion = criterion;
  double best = std::numeric_limits<double>::infinity();
  for (int d = 0; d <= std::min(max_degree, n - 2); ++d) {
    Eigen::VectorXd h;
    const FitResult f = fit_polynomial(x, y, d, 0.95, &h);
    DegreeScore s;
    s.degree = d;
    s.sse = f.sse;
    const Eigen::ArrayXd loo = f.residuals.array() / (1.0 - h.array());
    s.loocv_rmse = std::max(std::sqrt(loo.square().mean()), floor_rms);
    if (!std::isfinite(s.loocv_rmse)) s.loocv_rmse = std::numeric_limits<double>::infinity();
    const int k = d + 1;
    s.aic = n * std::log(std::max(f.sse, floor_sse) / n) + 2.0 * k;
    s.aicc = n - k - 1 > 0 ? s.aic + 2.0 * k * (k + 1) / (n - k - 1)
                           : std::numeric_limits<double>::infinity();
    sel.scores.push_back(s);
    const double score = criterion == DegreeCriterion::kAic    ? s.aic
                         : criterion == DegreeCriterion::kAicc ? s.aicc
                                                               : s.loocv_rmse;
    if (score < best) {
      best = score;
      sel.chosen_degree = d;
    }
  }
  return sel;
}

}  // namespace si::fit
