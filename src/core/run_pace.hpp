// How long a path run has left, from its pace (the `run` command's progress line,
// app/progress_line.hpp).
#pragma once

#include <optional>

namespace si {

// The time left to depth_max from the pace since the first point this process saw: a resumed
// run starts at its checkpoint's depth, so the depth it went from 0 is not what its clock timed
// (measured: 8.36 mm resumed at 8.19 mm, 136 s, said "ETA 27 s" for 54 s per 0.17 mm).
class RunPace {
 public:
  // A point at `depth` (mm), `seconds` after the clock's start.
  void add(double depth, double seconds);
  // Seconds to depth_max at the pace so far; none before a second point or while the depth has
  // not gone beyond the first point's (a snap-back, no progress).
  std::optional<double> remaining(double depth_max) const;

 private:
  std::optional<double> first_depth_, first_seconds_;
  double depth_ = 0, seconds_ = 0;
};

}  // namespace si
