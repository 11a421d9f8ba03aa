#include "core/run_pace.hpp"

namespace si {

void RunPace::add(double depth, double seconds) {
  if (!first_depth_) {
    first_depth_ = depth;
    first_seconds_ = seconds;
  }
  depth_ = depth;
  seconds_ = seconds;
}

std::optional<double> RunPace::remaining(double depth_max) const {
  if (!first_depth_ || !(depth_ > *first_depth_) || !(depth_ < depth_max)) return std::nullopt;
  return (seconds_ - *first_seconds_) / (depth_ - *first_depth_) * (depth_max - depth_);
}

}  // namespace si
