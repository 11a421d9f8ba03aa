#include "core/run_pace.hpp"

namespace si {

void RunPace::add(double depth, double seconds) {
  window_.push_back({depth, seconds});
  if (!first_step_dropped_ && window_.size() == 3) {
    window_.pop_front();  // the first step's start: a second step now gives the pace
    first_step_dropped_ = true;
  }
  while (window_.size() > kWindowSteps + 1) window_.pop_front();
}

std::optional<double> RunPace::remaining(double depth_max) const {
  if (window_.size() < 2) return std::nullopt;
  const Point& from = window_.front();
  const Point& to = window_.back();
  if (!(to.depth > from.depth) || !(to.depth < depth_max)) return std::nullopt;
  return (to.seconds - from.seconds) / (to.depth - from.depth) * (depth_max - to.depth);
}

}  // namespace si
