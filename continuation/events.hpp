// Event detection between two consecutive points of a branch and location on the segment
// between them (docs/theory/continuation.md, "Events").
//
// Every event is the sign change of an indicator evaluated at a converged point:
//   limit point       g = dp/ds (the tangent's p component)
//   extremum of m     g = dm/ds (max when g goes from + to -)
//   zero crossing     g = m
//   inflection a(b)   g = a'' b' - a' b''  (= b'^3 d2a/db2, so its sign change is an inflection
//                     of a against b while b is monotone; derivatives along s, point_analysis.hpp)
//   slope extremum    the same with b = p: an extremum of dm/dp (curve_features.hpp)
//   signature change  the discrete Problem::signature()
//   bifurcation       sign det [J F_p; t'] = sign(det J) sign(dp/ds) (Keller 1977: constant
//                     through simple limit points, changes at simple bifurcation points)
//   stability change  the number of negative eigenvalues (stability_events.hpp)
// A change between A and B is located on the segment by re-solving the corrector at local
// coordinates sigma in (0, sigma_B) (event_location.hpp). Inflections and slope extrema go through
// the curve-feature detector, which reports only resolved, confirmed sign changes away from
// signature changes (curve_features.hpp). Two sign changes of one indicator within one step cancel
// and are not seen: the step control keeps steps small relative to the branch's features.
#pragma once

#include <string>
#include <vector>

#include "continuation/event_location.hpp"

namespace si::cont {

struct Indicator {
  EventType type = EventType::kLimitPoint;
  int monitor = -1;    // index into the monitor names (extrema, zero crossings, features)
  int against = -1;    // inflections: the abscissa monitor; slope extrema: -1 (the parameter)
  double level = 0.0;  // zero crossings: of m - level (Settings::level_crossings)
  double value_tolerance = 0.0;  // level crossings: LevelCrossing::value_tolerance
};

// The indicators asked for by the settings. Throws std::invalid_argument naming an unknown
// monitor ("continuation.extremum_monitors: unknown monitor 'F' (known: ...)").
std::vector<Indicator> make_indicators(const Settings& settings,
                                       const std::vector<std::string>& monitor_names);

// What point_analysis must compute for these indicators (stability: Settings::stability_modes).
AnalysisNeeds analysis_needs(const std::vector<Indicator>& indicators, const Settings& settings,
                             const std::vector<std::string>& monitor_names);

// The extent of each monitor and of p over the accepted points so far: the curve's own scale for
// the curve-feature detector.
struct CurveScales {
  Vector low;
  Vector high;
  double p_low = 0.0;
  double p_high = 0.0;
  bool empty = true;
  void include(const Point& point);
  double monitor_range(int i) const;
  double p_range() const { return empty ? 0.0 : p_high - p_low; }
};

// An event of `type` at the point `at` (type, name, monitor names, p, x, monitors, branch id);
// the caller sets step, arclength and the location fields.
Event event_at(EventType type, const Indicator& indicator,
               const std::vector<std::string>& monitor_names, const TangentPoint& at);

// The solvers of the points inside a step: `plain` for every event but a stability change, whose
// location needs each point's stability (`with_stability`; the same as plain when the
// continuation computes none), and a monitor's zero or level crossing, which reads the monitors
// alone (`monitors_only`: no tangent, no factorization at the trial points).
struct SegmentSolvers {
  SegmentSolver plain;
  SegmentSolver with_stability;
  SegmentSolver monitors_only;
};

// Events whose indicators change between a and b (b at local coordinate sigma_b), located,
// tagged with `step` (the index b will have in the branch) and sorted by position.
std::vector<Event> find_events(const std::vector<Indicator>& indicators,
                               const std::vector<std::string>& monitor_names, const TangentPoint& a,
                               const TangentPoint& b, double sigma_b, const SegmentSolvers& solve,
                               const Settings& settings, int step, BorderedSolver& metric,
                               const CurveScales& scales);

}  // namespace si::cont
