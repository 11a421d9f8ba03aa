#include "analysis/critical_force.hpp"

#include "analysis/grid_features.hpp"
#include "analysis/path_columns.hpp"

namespace si {
namespace {

const PathColumn kCurvatures[] = {PathColumn::kK11, PathColumn::kK12, PathColumn::kK22};

// The (T, k) curve at interior point i as the library's Point: derivatives in the depth by
// three-point divided differences on the (possibly uneven) grid, the second's error from the
// solves' accuracy.
cont::Point grid_point(const std::vector<PathPoint>& pts, int i, int curvature,
                       const Eigen::Vector2d& magnitude) {
  const auto value = [&](int j) {
    return Eigen::Vector2d(pts[j].state.force, pts[j].state.apex_curvature[curvature]);
  };
  const DifferenceWeights w = difference_weights(pts[i].state.depth - pts[i - 1].state.depth,
                                                 pts[i + 1].state.depth - pts[i].state.depth);
  const Eigen::Vector2d f0 = value(i - 1), f1 = value(i), f2 = value(i + 1);
  cont::Point p;
  p.p = pts[i].state.depth;
  p.tangent_p = 1;
  p.monitors = f1;
  p.monitor_slopes = w.first(0) * f0 + w.first(1) * f1 + w.first(2) * f2;
  p.monitor_curvatures = w.second(0) * f0 + w.second(1) * f1 + w.second(2) * f2;
  p.monitor_curvature_errors = w.second.cwiseAbs().sum() * kPointAccuracy * magnitude;
  return p;
}

}  // namespace

std::vector<cont::Event> critical_force_events(const std::vector<PathPoint>& points,
                                               int curvature) {
  cont::CurveScales scales;
  Eigen::Vector2d magnitude = Eigen::Vector2d::Zero();
  for (const PathPoint& pt : points) {
    cont::Point p;
    p.p = pt.state.depth;
    p.monitors = Eigen::Vector2d(pt.state.force, pt.state.apex_curvature[curvature]);
    scales.include(p);
    magnitude = magnitude.cwiseMax(p.monitors.cwiseAbs());
  }
  const cont::Indicator inflection{cont::EventType::kInflection, 0, 1};
  std::vector<cont::Event> events = grid_features(
      points, inflection, [&](int i) { return grid_point(points, i, curvature, magnitude); },
      scales);
  for (cont::Event& e : events) {
    e.monitor = column_name(PathColumn::kForce);
    e.against = column_name(kCurvatures[curvature]);
  }
  return events;
}

}  // namespace si
