#include "continuation/stability_events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace si::cont {
namespace {

// The j-th lowest eigenvalue (1-based) at a point, NaN if not computed.
double eigenvalue(const Point& pt, int j) {
  return j >= 1 && j <= pt.eigenvalues.size() ? pt.eigenvalues(j - 1)
                                              : std::numeric_limits<double>::quiet_NaN();
}

bool opposite_signs(double u, double v) {
  return (u > 0.0 && v < 0.0) || (u < 0.0 && v > 0.0);
}

// dp/ds at the step's two ends: the parameter turns within the step at a fold, and keeps its
// direction through a bifurcation. (dp/ds at the event point itself is no test: at a bifurcation
// the bordered matrix is singular too, and the tangent solved there is any mix of the two
// branches' tangents, the closer the event is located the more so.)
Criticality classify(double a, double b) {
  return opposite_signs(a, b) ? Criticality::kLimitPoint : Criticality::kBifurcation;
}

}  // namespace

std::vector<Event> stability_events(const Indicator& indicator, const SegmentPoint& a,
                                    const SegmentPoint& b, const SegmentSolver& solve,
                                    const Settings& settings) {
  const Point& pa = a.point.point;
  const Point& pb = b.point.point;
  const int na = pa.negative_eigenvalues;
  const int nb = pb.negative_eigenvalues;
  if (na < 0 || nb < 0 || na == nb) return {};
  const bool rising = nb > na;
  std::vector<Event> events;
  for (int j = std::min(na, nb) + 1; j <= std::max(na, nb); ++j) {
    TangentPoint at = b.point;
    bool located = false;
    double accuracy = b.sigma - a.sigma;
    if (settings.locate_stability_changes) {
      if (opposite_signs(eigenvalue(pa, j), eigenvalue(pb, j))) {
        const auto g = [j](const TangentPoint& tp) { return eigenvalue(tp.point, j); };
        accuracy = locate_root(g, a, b, solve, settings, at, located);
      } else {
        // The count crosses j - 1 | j here: bisection on "at least j negative".
        const auto value = [j](const TangentPoint& tp) {
          return std::vector<int>{tp.point.negative_eigenvalues >= j ? 1 : 0};
        };
        accuracy = locate_change(value, a, b, solve, settings, at, located);
      }
    }
    Event event = event_at(EventType::kStabilityChange, indicator, {}, at);
    event.located = located;
    event.accuracy = accuracy;
    event.criticality = classify(pa.tangent_p, pb.tangent_p);
    event.negative_before = rising ? j - 1 : j;
    event.negative_after = rising ? j : j - 1;
    event.eigenvalue = eigenvalue(at.point, j);
    if (j <= static_cast<int>(at.modes.size()))
      event.mode = at.modes[static_cast<std::size_t>(j - 1)];
    // The fundamental branch's tangent, for branch switching: the bracket's regular start's. At
    // the located point the bordered matrix is singular too (above), and the tangent solved there
    // may be any mix of the two branches' tangents: measured on Sze's roof, dp/ds 0.037 there
    // against 0.874 on the branch, which turned the switch's predictor back along the branch.
    const TangentPoint& regular = a.point.tangent_x.size() == at.tangent_x.size() ? a.point : at;
    event.tangent_x = regular.tangent_x;
    event.tangent_p = regular.point.tangent_p;
    events.push_back(std::move(event));
  }
  return events;
}

}  // namespace si::cont
