// How long a path run has left, from its pace (the `run` command's progress line,
// app/progress_line.hpp).
#pragma once

#include <cstddef>
#include <deque>
#include <optional>

namespace si {

// The time left to depth_max from the pace of the last few steps this process ran.
// - This process's points only: a resumed run starts at its checkpoint's depth, so the depth it
//   went from 0 is not what its clock timed (measured: 8.36 mm resumed at 8.19 mm, 136 s, said
//   "ETA 27 s" for 54 s per 0.17 mm).
// - Not the first step once there is another: from first touch it builds the contact set and the
//   preconditioner from nothing and costs many normal steps (the 1e6-unknown cap: 568 s for its
//   first 0.1 mm, then 52-60 s per 0.05 mm: averaged from the start, the ETA after the second
//   point said 11 h 25 min, after the sixth 7 h 41 min, for 1 h 25 min and 1 h 22 min left; this
//   pace says 3 h 3 min and 3 h 24 min: the steps grow later, docs/performance.md).
// - The last kWindowSteps steps only: a step's cost grows with the contact set, and the average
//   since the start lags behind it.
class RunPace {
 public:
  static constexpr std::size_t kWindowSteps = 8;

  // A point at `depth` (mm), `seconds` after the clock's start.
  void add(double depth, double seconds);
  // Seconds to depth_max at the recent pace; none before a second point or while the depth has
  // not gone beyond the window's first point (a snap-back, no progress).
  std::optional<double> remaining(double depth_max) const;

 private:
  struct Point {
    double depth, seconds;
  };
  std::deque<Point> window_;  // oldest first, at most kWindowSteps + 1 points
  bool first_step_dropped_ = false;
};

}  // namespace si
