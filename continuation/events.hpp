// Event detection between two consecutive points of a branch and location on the segment
// between them (docs/theory/continuation.md, "Events").
//
// Every event is the sign change of an indicator evaluated at a converged point:
//   limit point       g = dp/ds (the tangent's p component)
//   extremum of m     g = dm/ds (max when g goes from + to -)
//   zero crossing     g = m
//   inflection a(b)   g = a'' b' - a' b''  (= b'^3 d2a/db2, so its sign change is an inflection
//                     of a against b while b is monotone; derivatives along s, point_analysis.hpp)
//   signature change  the discrete Problem::signature()
//   bifurcation       sign det [J F_p; t'] = sign(det J) sign(dp/ds) (Keller 1977: constant
//                     through simple limit points, changes at simple bifurcation points)
// A change between A and B is located on the segment by re-solving the corrector at local
// coordinates sigma in (0, sigma_B): continuous indicators by the Illinois variant of regula
// falsi with a bisection safeguard, discrete ones by bisection, until the bracket is at most
// Settings::event_tolerance wide. Two sign changes of one indicator within one step cancel and
// are not seen: the step control keeps steps small relative to the branch's features.
#pragma once

#include <functional>
#include <vector>

#include "continuation/point_analysis.hpp"
#include "continuation/settings.hpp"

namespace si::cont {

struct Indicator {
  EventType type = EventType::kLimitPoint;
  int monitor = -1;  // index into the monitor names (extrema, zero crossings, inflections)
  int against = -1;  // inflections: the abscissa monitor
};

// The indicators asked for by the settings. Throws std::invalid_argument naming an unknown
// monitor ("continuation.extremum_monitors: unknown monitor 'F' (known: ...)").
std::vector<Indicator> make_indicators(const Settings& settings,
                                       const std::vector<std::string>& monitor_names);

// What point_analysis must compute for these indicators.
AnalysisNeeds analysis_needs(const std::vector<Indicator>& indicators);

// Puts a converged, analysed point on the current segment at local coordinate sigma.
using SegmentSolver = std::function<bool(double sigma, TangentPoint& out)>;

// The root of the continuous function g on (0, sigma_b) where g(a) and g(b) differ in sign, by
// Illinois regula falsi with bisection safeguard; `out` receives the bracket end with the
// smaller |g|. Returns the final bracket width (0 if g hit exactly 0); `located` is set when it
// is <= tolerance.
double locate_root(const std::function<double(const TangentPoint&)>& g, const TangentPoint& a,
                   const TangentPoint& b, double sigma_b, const SegmentSolver& solve,
                   const Settings& settings, TangentPoint& out, bool& located);

// Events whose indicators change between a and b (b at local coordinate sigma_b), located,
// tagged with `step` (the index b will have in the branch) and sorted by position.
std::vector<Event> find_events(const std::vector<Indicator>& indicators,
                               const std::vector<std::string>& monitor_names, const TangentPoint& a,
                               const TangentPoint& b, double sigma_b, const SegmentSolver& solve,
                               const Settings& settings, int step, BorderedSolver& metric);

}  // namespace si::cont
