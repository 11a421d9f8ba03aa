// The `run` command's progress line: one line per converged point (overwriting itself on a
// terminal), a line of its own per failed step, and the time left from the run's pace.
#pragma once

#include <chrono>
#include <ostream>

#include "analysis/indentation_run.hpp"
#include "continuation/settings.hpp"
#include "core/run_pace.hpp"

namespace si {

class ProgressLine {
 public:
  ProgressLine(std::ostream& err, double depth_max);
  void show(const PathPoint& p);
  void failed(const cont::StepFailure& f);
  void done();

 private:
  std::ostream& err_;
  double depth_max_;
  bool tty_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  RunPace pace_;
};

}  // namespace si
