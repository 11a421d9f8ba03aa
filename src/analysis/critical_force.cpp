#include "analysis/critical_force.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/path_columns.hpp"
#include "continuation/curve_features.hpp"

namespace si {
namespace {

const PathColumn kCurvatures[] = {PathColumn::kK11, PathColumn::kK12, PathColumn::kK22};

// The relative accuracy of a grid point's values (the fast path's direct solve, the active set's
// 1e-10 tolerance on the force), per unit of the coordinate's largest magnitude.
constexpr double kSolveAccuracy = 1e-9;

// The nodes pressing at a point (as contact_nodes counts them); empty per-node vectors (a point
// restored from values) give no set, and such a point no sign.
std::vector<int> contact_set(const IndentationState& s) {
  std::vector<int> set;
  double largest = 0;
  for (double l : s.multipliers) largest = std::max(largest, std::abs(l));
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (s.multipliers[i] > 1e-9 * largest && s.multipliers[i] > 0) set.push_back(s.nodes[i]);
  return set;
}

// The (T, k) curve at interior point i as the library's Point: derivatives in the depth by
// three-point divided differences on the (possibly uneven) grid, the second's error from the
// solves' accuracy.
cont::Point grid_point(const std::vector<PathPoint>& pts, int i, int curvature,
                       const Eigen::Vector2d& magnitude) {
  const auto value = [&](int j) {
    return Eigen::Vector2d(pts[j].state.force, pts[j].state.apex_curvature[curvature]);
  };
  const double h1 = pts[i].state.depth - pts[i - 1].state.depth;
  const double h2 = pts[i + 1].state.depth - pts[i].state.depth;
  const Eigen::Vector2d f0 = value(i - 1), f1 = value(i), f2 = value(i + 1);
  cont::Point p;
  p.p = pts[i].state.depth;
  p.tangent_p = 1;
  p.monitors = f1;
  p.monitor_slopes =
      (-h2 / (h1 * (h1 + h2))) * f0 + ((h2 - h1) / (h1 * h2)) * f1 + (h1 / (h2 * (h1 + h2))) * f2;
  const double c0 = 2 / (h1 * (h1 + h2)), c1 = 2 / (h1 * h2), c2 = 2 / (h2 * (h1 + h2));
  p.monitor_curvatures = c0 * f0 - c1 * f1 + c2 * f2;
  p.monitor_curvature_errors = (c0 + c1 + c2) * kSolveAccuracy * magnitude;
  return p;
}

}  // namespace

std::vector<cont::Event> critical_force_events(const std::vector<PathPoint>& points,
                                               int curvature) {
  const int n = static_cast<int>(points.size());
  std::vector<cont::Event> events;
  if (n < 4) return events;
  std::vector<std::vector<int>> sets(static_cast<std::size_t>(n));
  cont::CurveScales scales;
  Eigen::Vector2d magnitude = Eigen::Vector2d::Zero();
  for (int i = 0; i < n; ++i) {
    sets[i] = contact_set(points[i].state);
    cont::Point p;
    p.p = points[i].state.depth;
    p.monitors = Eigen::Vector2d(points[i].state.force, points[i].state.apex_curvature[curvature]);
    scales.include(p);
    magnitude = magnitude.cwiseMax(p.monitors.cwiseAbs());
  }
  const cont::Indicator inflection{cont::EventType::kInflection, 0, 1};
  const cont::Settings rules;  // the library's noise factor and curvature tolerance
  // Signs at interior points whose stencil lies on one contact set (rule 4), resolved (1, 2).
  std::vector<int> sign(static_cast<std::size_t>(n), 0);
  std::vector<double> g(static_cast<std::size_t>(n), 0.0);
  for (int i = 1; i + 1 < n; ++i) {
    if (sets[i].empty() || sets[i - 1] != sets[i] || sets[i + 1] != sets[i]) continue;
    const cont::FeatureValue v =
        cont::feature_value(inflection, grid_point(points, i, curvature, magnitude), scales);
    g[i] = v.g;
    sign[i] = cont::resolved_sign(v, rules);
  }
  // A change between two signed points, the points between them unsigned (e.g. one on the
  // inflection itself) and every stencil from the first to the last on one contact set.
  int last = -1;  // the last signed point
  for (int j = 1; j + 1 < n; ++j) {
    if (sets[j] != sets[j - 1]) last = -1;  // a kink: no change across it
    if (sign[j] == 0) continue;
    const int i = last;
    last = j;
    if (i < 0 || sign[j] != -sign[i]) continue;
    const IndentationState& a = points[i].state;
    const IndentationState& b = points[j].state;
    const double t = g[i] / (g[i] - g[j]);  // g linear between the two points
    cont::Event e;
    e.type = cont::EventType::kInflection;
    e.name = cont::event_type_name(e.type);
    e.monitor = column_name(PathColumn::kForce);
    e.against = column_name(kCurvatures[curvature]);
    e.p = a.depth + t * (b.depth - a.depth);
    e.monitors = (1 - t) * monitor_values(a) + t * monitor_values(b);
    e.step = j;
    e.located = false;
    e.accuracy = std::abs(b.depth - a.depth);
    events.push_back(e);
  }
  return events;
}

}  // namespace si
