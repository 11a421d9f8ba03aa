// What a continuation run returns: the accepted points, the located events, and why it ended.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "continuation/problem.hpp"

namespace si::cont {

// One accepted point of the branch. Derivatives are with respect to the arclength s in the norm
// sqrt(<dx, dx> + w^2 dp^2) (w = Settings::parameter_weight), along the direction of travel.
struct Point {
  Vector x;
  double p = 0.0;
  double tangent_p = 0.0;  // dp/ds of the unit tangent; 0 at a limit point of p
  Vector monitors;         // values, in Problem::monitor_names() order
  // dm/ds and d2m/ds2 along the branch: filled only when an event needs them (extrema,
  // inflections), else empty.
  Vector monitor_slopes;
  Vector monitor_curvatures;
  std::vector<int> signature;  // Problem::signature()
  int jacobian_sign = 0;       // Problem::jacobian_sign() at the point (0 = unknown)
  int newton_iterations = 0;   // corrector iterations that produced the point
  double step = 0.0;           // step size that produced it (0 for the start point)
  double arclength = 0.0;      // accumulated chord length from the start point
};

enum class EventType {
  kLimitPoint,       // dp/ds = 0 (turning point)
  kMonitorMax,       // dm/ds from + to -
  kMonitorMin,       // dm/ds from - to +
  kZeroCrossing,     // m = 0
  kSignatureChange,  // Problem::signature() changed
  kInflection,       // d2a/db2 changes sign (a = monitor, b = against)
  kBifurcation,      // sign of det of the augmented Jacobian changed (needs jacobian_sign)
};
// "limit_point", "monitor_max", "monitor_min", "zero_crossing", "signature_change",
// "inflection", "bifurcation".
std::string event_type_name(EventType type);

struct Event {
  EventType type = EventType::kLimitPoint;
  std::string name;     // event_type_name(type)
  std::string monitor;  // the monitor concerned (empty for limit points, signature, bifurcation)
  std::string against;  // inflections: the abscissa monitor
  double p = 0.0;
  Vector x;
  Vector monitors;  // monitor values at the event
  // The event lies between points[step - 1] and points[step] of the branch.
  int step = 0;
  // located: the indicator's bracket was shrunk to <= Settings::event_tolerance (arclength,
  // |dp| for natural). accuracy: the final bracket width (the step itself if not located).
  bool located = false;
  double accuracy = 0.0;
  double arclength = 0.0;  // of the event point, from the start
};

enum class Status {
  kRunning,            // never returned; a checkpoint taken mid-run carries it
  kCompleted,          // natural: the last of Settings::parameter_values was reached
  kReachedBound,       // p reached p_min or p_max (the last point lies on it)
  kMaxSteps,           // Settings::max_steps accepted steps
  kStepTooSmall,       // a step failed at step_min; `reason` says why
  kStoppedByCallback,  // the callback returned false
  kStartFailed,        // the start point did not converge; `reason` says why
};
std::string status_name(Status status);

struct Branch {
  std::vector<std::string> monitor_names;
  std::vector<Point> points;
  std::vector<Event> events;
  Status status = Status::kRunning;
  std::string reason;
  int failed_steps = 0;  // corrector failures that were retried with a smaller step
};

// Called after each accepted point (the start point included), after its events were added to
// the branch; returning false stops the run (Status::kStoppedByCallback) keeping the point.
using Callback = std::function<bool(const Point&, const Branch&)>;

}  // namespace si::cont
