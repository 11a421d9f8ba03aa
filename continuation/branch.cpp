#include "continuation/branch.hpp"

namespace si::cont {

std::string event_type_name(EventType type) {
  switch (type) {
    case EventType::kLimitPoint:
      return "limit_point";
    case EventType::kMonitorMax:
      return "monitor_max";
    case EventType::kMonitorMin:
      return "monitor_min";
    case EventType::kZeroCrossing:
      return "zero_crossing";
    case EventType::kSignatureChange:
      return "signature_change";
    case EventType::kInflection:
      return "inflection";
    case EventType::kBifurcation:
      return "bifurcation";
    case EventType::kStabilityChange:
      return "stability_change";
    case EventType::kSlopeMax:
      return "slope_max";
    case EventType::kSlopeMin:
      return "slope_min";
  }
  return "unknown";
}

std::string criticality_name(Criticality criticality) {
  switch (criticality) {
    case Criticality::kNone:
      return "none";
    case Criticality::kLimitPoint:
      return "limit_point";
    case Criticality::kBifurcation:
      return "bifurcation";
  }
  return "unknown";
}

std::string status_name(Status status) {
  switch (status) {
    case Status::kRunning:
      return "running";
    case Status::kCompleted:
      return "completed";
    case Status::kReachedBound:
      return "reached_bound";
    case Status::kMaxSteps:
      return "max_steps";
    case Status::kStepTooSmall:
      return "step_too_small";
    case Status::kStoppedByCallback:
      return "stopped_by_callback";
    case Status::kStartFailed:
      return "start_failed";
  }
  return "unknown";
}

}  // namespace si::cont
