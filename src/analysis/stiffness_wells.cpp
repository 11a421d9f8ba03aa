#include "analysis/stiffness_wells.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace si {
namespace {

// The wells of the minima of v (a maximum of s is a minimum of -s): each sample in ascending
// order of v opens the run of its neighbours within fraction |v| of it; the run is a well if it is
// bounded on both sides and holds nothing lower (else it is a larger run around a lower well).
std::vector<StiffnessWell> minimum_wells(const std::vector<double>& v, double fraction,
                                         CriticalKind kind) {
  const int n = static_cast<int>(v.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return v[a] < v[b]; });
  std::vector<bool> covered(n, false);
  std::vector<StiffnessWell> wells;
  for (int m : order) {
    if (covered[m]) continue;
    const double threshold = v[m] + fraction * std::abs(v[m]);
    int first = m, last = m;
    while (first > 0 && v[first - 1] <= threshold) --first;
    while (last + 1 < n && v[last + 1] <= threshold) ++last;
    const bool lowest =
        std::all_of(v.begin() + first, v.begin() + last + 1, [&](double x) { return x >= v[m]; });
    std::fill(covered.begin() + first, covered.begin() + last + 1, true);
    if (first == 0 || last == n - 1 || !lowest) continue;
    StiffnessWell w;
    w.kind = kind;
    w.first = first;
    w.last = last;
    wells.push_back(w);
  }
  return wells;
}

}  // namespace

std::vector<StiffnessWell> stiffness_wells(const std::vector<StiffnessSample>& samples,
                                           double fraction) {
  std::vector<double> s(samples.size()), minus_s(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    s[i] = samples[i].stiffness;
    minus_s[i] = -s[i];
  }
  std::vector<StiffnessWell> wells = minimum_wells(s, fraction, CriticalKind::kStiffnessMin);
  for (const StiffnessWell& w : minimum_wells(minus_s, fraction, CriticalKind::kStiffnessMax))
    wells.push_back(w);
  for (StiffnessWell& w : wells) {
    w.from = samples[w.first - 1].depth;
    w.to = samples[w.last + 1].depth;
  }
  std::sort(wells.begin(), wells.end(),
            [](const StiffnessWell& a, const StiffnessWell& b) { return a.from < b.from; });
  return wells;
}

std::optional<StiffnessVertex> fitted_vertex(const std::vector<StiffnessSample>& samples,
                                             const StiffnessWell& well) {
  const int n = well.last - well.first + 1;
  if (n < 5) return std::nullopt;
  // Centred and scaled depths keep the 3 x 3 normal matrix well conditioned.
  const double lo = samples[well.first].depth, hi = samples[well.last].depth;
  const double centre = 0.5 * (lo + hi), scale = 0.5 * (hi - lo);
  if (!(scale > 0)) return std::nullopt;
  Eigen::MatrixXd X(n, 3);
  Eigen::VectorXd y(n);
  for (int k = 0; k < n; ++k) {
    const double x = (samples[well.first + k].depth - centre) / scale;
    X.row(k) << 1.0, x, x * x;
    y(k) = samples[well.first + k].stiffness;
  }
  const Eigen::Matrix3d normal = X.transpose() * X;
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
  if (ldlt.info() != Eigen::Success) return std::nullopt;
  const Eigen::Vector3d c = ldlt.solve(X.transpose() * y);
  const double rss = (y - X * c).squaredNorm();
  const Eigen::Matrix3d covariance = ldlt.solve(Eigen::Matrix3d::Identity()) * (rss / (n - 3));
  const double sign = well.kind == CriticalKind::kStiffnessMin ? 1.0 : -1.0;
  const double c2_error = std::sqrt(std::max(covariance(2, 2), 0.0));
  // The well's sign, standing out of the scatter (strictly: an exact flat well has none).
  if (!(sign * c(2) > kCurvatureSignificance * c2_error)) return std::nullopt;
  const double x = -c(1) / (2 * c(2));
  if (x < -1 || x > 1) return std::nullopt;
  // The vertex's variance by the delta method: gradient of -c1 / (2 c2) in (c0, c1, c2).
  const Eigen::Vector3d g(0.0, -1 / (2 * c(2)), c(1) / (2 * c(2) * c(2)));
  const double x_error = std::sqrt(std::max(g.dot(covariance * g), 0.0));
  StiffnessVertex v;
  v.depth = centre + scale * x;
  v.stiffness = c(0) + c(1) * x + c(2) * x * x;
  // Exact data (a smooth parabolic well) leave no scatter: the fit's own roundoff then.
  v.accuracy = std::max(2 * scale * x_error, 1e-12 * (1 + std::abs(v.depth)));
  return v;
}

}  // namespace si
