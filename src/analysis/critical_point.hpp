// The named critical points of a path (issue 15 item 4; docs/theory/continuation.md 14), as
// data: what analysis/critical_points.hpp finds on a run's converged points and events, and
// io/ writes (path.json `critical_points`, sweep.csv, the run's summary).
#pragma once

#include <limits>
#include <optional>
#include <vector>

namespace si {

enum class CriticalKind {
  kNonlinearityOnset,  // |T - T_lin| reaches path.nonlinearity_fraction of T_lin
  kStiffnessMin,       // a minimum of the tangent stiffness dT/dh over a well of 5 % of it
  kStiffnessMax,       // a maximum of dT/dh, the same (analysis/stiffness_wells.hpp)
  kDepthTurn,          // dh/ds = 0: the depth turns (snap-back), a limit point under depth control
  kForceMax,           // dT/ds = 0 from + to -: a limit point under force control (snap-through)
  kForceMin,           // dT/ds = 0 from - to +
  kBifurcation,        // a stability change whose depth does not turn (path.stability)
};

struct CriticalPoint {
  CriticalKind kind = CriticalKind::kNonlinearityOnset;
  double depth = std::numeric_limits<double>::quiet_NaN();  // mm, travel after first touch
  double force = std::numeric_limits<double>::quiet_NaN();  // N, whole shell
  // The depth's error bound (mm) for the onset and the inflections; for the events of the
  // continuation (limit points, bifurcations) their bracket (cont::Event::accuracy).
  double accuracy = std::numeric_limits<double>::quiet_NaN();
  bool located = false;  // shrunk below its bracket of converged points
  double stiffness = std::numeric_limits<double>::quiet_NaN();     // dT/dh (N/mm), inflections
  double linear_force = std::numeric_limits<double>::quiet_NaN();  // T_lin (N), the onset
};

// Why the onset has, or has not, a value.
enum class OnsetStatus {
  kFound,
  kNone,              // the deviation stays below the fraction over the whole path
  kLinearKinematics,  // the run is the linear response itself
  kLocalLaw,          // contact.local: no linear fast path to compare with
  kTooFewPoints,
  kSupportFrame,  // a fixture's frame: the linear fast path knows the indenter's rows only
};

struct CriticalPoints {
  double nonlinearity_fraction = 0.05;
  OnsetStatus onset_status = OnsetStatus::kTooFewPoints;
  std::optional<CriticalPoint> onset;
  double max_deviation = std::numeric_limits<double>::quiet_NaN();  // max |T - T_lin| / T_lin
  std::vector<CriticalPoint> inflections;   // kStiffnessMin, kStiffnessMax, in depth order
  std::vector<CriticalPoint> limit_points;  // kDepthTurn, kForceMax, kForceMin
  bool stability = false;                   // path.stability: bifurcations were looked for
  std::vector<CriticalPoint> bifurcations;
};

}  // namespace si
