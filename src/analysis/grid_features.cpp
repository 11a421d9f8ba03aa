#include "analysis/grid_features.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/path_columns.hpp"
#include "continuation/curve_features.hpp"

namespace si {

std::vector<int> pressing_nodes(const IndentationState& s) {
  std::vector<int> set;
  double largest = 0;
  for (double l : s.multipliers) largest = std::max(largest, std::abs(l));
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (s.multipliers[i] > 1e-9 * largest && s.multipliers[i] > 0) set.push_back(s.nodes[i]);
  return set;
}

DifferenceWeights difference_weights(double h1, double h2) {
  DifferenceWeights w;
  w.first << -h2 / (h1 * (h1 + h2)), (h2 - h1) / (h1 * h2), h1 / (h2 * (h1 + h2));
  w.second << 2 / (h1 * (h1 + h2)), -2 / (h1 * h2), 2 / (h2 * (h1 + h2));
  return w;
}

std::vector<cont::Event> grid_features(const std::vector<PathPoint>& points,
                                       const cont::Indicator& indicator, const GridPoint& at,
                                       const cont::CurveScales& scales) {
  const int n = static_cast<int>(points.size());
  std::vector<cont::Event> events;
  if (n < 4) return events;
  std::vector<std::vector<int>> sets(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) sets[i] = pressing_nodes(points[i].state);
  const cont::Settings rules;  // the library's noise factor and curvature tolerance
  // Signs at interior points whose stencil lies on one contact set (rule 4), resolved (1, 2).
  std::vector<int> sign(static_cast<std::size_t>(n), 0);
  std::vector<double> g(static_cast<std::size_t>(n), 0.0);
  for (int i = 1; i + 1 < n; ++i) {
    if (sets[i].empty() || sets[i - 1] != sets[i] || sets[i + 1] != sets[i]) continue;
    const cont::FeatureValue v = cont::feature_value(indicator, at(i), scales);
    g[i] = v.g;
    sign[i] = cont::resolved_sign(v, rules);
  }
  // A change between two signed points, the points between them unsigned (e.g. one on the
  // feature itself) and every stencil from the first to the last on one contact set.
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
    e.type = indicator.type == cont::EventType::kInflection ? cont::EventType::kInflection
             : sign[i] > 0                                  ? cont::EventType::kSlopeMax
                                                            : cont::EventType::kSlopeMin;
    e.name = cont::event_type_name(e.type);
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
