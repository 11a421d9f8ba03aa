#include "analysis/critical_force.hpp"

#include <cmath>

#include "analysis/path_columns.hpp"

namespace si {
namespace {

const PathColumn kCurvatures[] = {PathColumn::kK11, PathColumn::kK12, PathColumn::kK22};

}  // namespace

std::vector<cont::Event> critical_force_events(const std::vector<PathPoint>& points, int curvature,
                                               int persistence) {
  const int n = static_cast<int>(points.size());
  // Signed second derivative at interior points (0 where undefined: equal abscissae).
  std::vector<int> sign(n, 0);
  for (int i = 1; i + 1 < n; ++i) {
    const double x0 = points[i - 1].state.apex_curvature[curvature];
    const double x1 = points[i].state.apex_curvature[curvature];
    const double x2 = points[i + 1].state.apex_curvature[curvature];
    const double y0 = points[i - 1].state.force, y1 = points[i].state.force,
                 y2 = points[i + 1].state.force;
    if (x1 == x0 || x2 == x1 || x2 == x0) continue;
    const double d2 = 2 * ((y2 - y1) / (x2 - x1) - (y1 - y0) / (x1 - x0)) / (x2 - x0);
    sign[i] = d2 > 0 ? 1 : (d2 < 0 ? -1 : 0);
  }
  // Points where the sign is defined and non-zero (an exact zero sits inside a change).
  std::vector<int> at;
  for (int i = 0; i < n; ++i)
    if (sign[i] != 0) at.push_back(i);
  std::vector<cont::Event> events;
  const int m = static_cast<int>(at.size());
  for (int j = persistence - 1; j + persistence < m; ++j) {
    bool change = sign[at[j + 1]] == -sign[at[j]];
    for (int k = 1; change && k < persistence; ++k)
      change = sign[at[j - k]] == sign[at[j]] && sign[at[j + 1 + k]] == sign[at[j + 1]];
    if (!change) continue;
    const int i = at[j], i2 = at[j + 1];
    const IndentationState& a = points[i].state;
    const IndentationState& b = points[i2].state;
    cont::Event e;
    e.type = cont::EventType::kInflection;
    e.name = cont::event_type_name(e.type);
    e.monitor = column_name(PathColumn::kForce);
    e.against = column_name(kCurvatures[curvature]);
    e.p = 0.5 * (a.depth + b.depth);
    e.monitors = 0.5 * (monitor_values(a) + monitor_values(b));
    e.step = i2;
    e.located = false;
    e.accuracy = std::abs(b.depth - a.depth);
    events.push_back(e);
  }
  return events;
}

}  // namespace si
