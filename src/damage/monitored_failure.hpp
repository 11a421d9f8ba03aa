// The governing failure index of one criterion over the points a run monitors (the nodes near
// the indenter, analysis/damage_probe.hpp): the value of its result column and, where it reaches
// 1, what its onset event reports (mode, ply or interface, position through the thickness, node).
#pragma once

#include <limits>

#include "damage/failure_index.hpp"
#include "damage/through_thickness_failure.hpp"

namespace si {

inline constexpr int kCriteria = 4;  // the entries of Criterion

struct MonitoredFailure {
  double index = std::numeric_limits<double>::quiet_NaN();  // NaN: not monitored
  FailureMode mode = FailureMode::kNone;
  int ply = 0;  // 0-based, bottom ply first; an interface: the ply above it
  PlyPosition position = PlyPosition::kBottom;
  bool interface = false;  // the interlaminar criterion: at the interface below `ply`
  double x3 = 0;           // mm from the mid-surface
  int node = -1;           // mesh node
};

}  // namespace si
