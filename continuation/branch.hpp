// What a continuation run returns: the accepted points, the located events, and why it ended.
#pragma once

#include <functional>
#include <limits>
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
  // Inflections only: error estimates of monitor_curvatures (|d2m/ds2 at step h - at 2h|, floored
  // by roundoff), d2p/ds2 and its error estimate (point_analysis.hpp); else empty / 0.
  Vector monitor_curvature_errors;
  double parameter_curvature = 0.0;
  double parameter_curvature_error = 0.0;
  std::vector<int> signature;  // Problem::signature()
  int jacobian_sign = 0;       // Problem::jacobian_sign() at the point (0 = unknown)
  int newton_iterations = 0;   // corrector iterations that produced the point
  double step = 0.0;           // step size that produced it (0 for the start point)
  double arclength = 0.0;      // accumulated chord length from the start point
  // Stability (Settings::stability_modes > 0, Problem::stability); negative_eigenvalues = -1
  // when not computed.
  int negative_eigenvalues = -1;  // of the tangent restricted to the problem's constraints
  int zero_eigenvalues = 0;       // numerically zero: a critical point to the pivots' accuracy
  bool stable = false;            // no negative and no zero eigenvalue
  double lowest_eigenvalue = std::numeric_limits<double>::quiet_NaN();
  Vector eigenvalues;  // the lowest Settings::stability_modes, ascending
  int branch_id = 0;   // 0: the run's own branch; switch_branch numbers the branches it starts
};

enum class EventType {
  kLimitPoint,       // dp/ds = 0 (turning point)
  kMonitorMax,       // dm/ds from + to -
  kMonitorMin,       // dm/ds from - to +
  kZeroCrossing,     // m = 0
  kSignatureChange,  // Problem::signature() changed
  kInflection,       // d2a/db2 changes sign (a = monitor, b = against)
  kBifurcation,      // sign of det of the augmented Jacobian changed (needs jacobian_sign)
  kStabilityChange,  // the number of negative eigenvalues changed (Settings::stability_modes)
  kSlopeMax,         // dm/dp has a maximum (inflection of m against p)
  kSlopeMin,         // dm/dp has a minimum: the minimum tangent stiffness of a force monitor
};
// "limit_point", "monitor_max", "monitor_min", "zero_crossing", "signature_change",
// "inflection", "bifurcation", "stability_change", "slope_max", "slope_min".
std::string event_type_name(EventType type);

// What a stability change is (docs/theory/continuation.md, "Stability events"): at a limit point
// the tangent's dp/ds vanishes with the eigenvalue; at a bifurcation it does not.
enum class Criticality { kNone, kLimitPoint, kBifurcation };
// "none", "limit_point", "bifurcation".
std::string criticality_name(Criticality criticality);

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
  int branch_id = 0;       // Point::branch_id of the branch it lies on

  // Stability changes only (else kNone / -1 / NaN / empty): the classification, the negative
  // counts on either side, the eigenvalue that crosses zero at the event point, its mode (in x),
  // and the branch's unit tangent there (what switch_branch needs).
  Criticality criticality = Criticality::kNone;
  int negative_before = -1;
  int negative_after = -1;
  double eigenvalue = std::numeric_limits<double>::quiet_NaN();
  Vector mode;
  Vector tangent_x;
  double tangent_p = 0.0;
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
  // How many of `points` the last checkpoint holds (written by this run, or the one it resumed
  // from): a resume continues from points[checkpointed - 1]. 0: no checkpoint.
  std::size_t checkpointed = 0;
};

// Called after each accepted point (the start point included), after its events were added to
// the branch; returning false stops the run (Status::kStoppedByCallback) keeping the point.
using Callback = std::function<bool(const Point&, const Branch&)>;

}  // namespace si::cont
