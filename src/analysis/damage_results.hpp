// What a run with a `damage:` section reports beside its columns (docs/results.md, `damage` in
// path.json; docs/theory/failure.md 6 items 3-5):
//  * per monitored criterion, its onset: the event where the largest index reaches 1 (located
//    by the continuation's event machinery, or by Brent's method on the linear fast path's exact
//    solves), with the mode, the ply or interface, the position through the thickness, the node,
//    the depth, the force and the indenter work there (the work on path.csv's trapezoidal
//    interpolation, so that impact energy and event agree: depth_at_energy(work) = depth);
//  * the Davies-Zhang (Olsson) delamination threshold with its inputs, and the depth where the
//    path's force first reaches it;
//  * the depth and force at each requested impact energy (damage/impact_energy.hpp, trapezoid:
//    the work column's own integration), `beyond_path` above the path's largest work.
#pragma once

#include <optional>
#include <vector>

#include "damage/delamination_threshold.hpp"
#include "damage/impact_energy.hpp"
#include "damage/monitored_failure.hpp"

namespace si {

struct IndentationSetup;
struct PathResult;

struct DamageOnset {
  Criterion criterion = Criterion::kHashin;
  int event = -1;                         // position in PathResult::events
  double depth = 0, force = 0, work = 0;  // mm, N, N mm
  MonitoredFailure at;                    // mode, ply or interface, x3, node
  bool located = false;
  double accuracy = 0;  // mm of depth (the event's bracket)
};

struct DamageResults {
  std::vector<DamageOnset> onsets;  // in path order
  std::optional<DelaminationThreshold> threshold;
  double threshold_depth =
      0;  // mm, where the path's force first reaches the threshold; NaN if never
  std::vector<EnergyPoint> energies;
};

// The event name of an onset in events.json.
inline constexpr const char* kDamageOnsetEvent = "damage_onset";

// The onset's location on the continuation stops when the index is within this of 1 (the
// level crossing's value tolerance, continuation/event_location.hpp): the onset force is then
// known to about 1e-7 relative (an index grows about in proportion to the force), far below the
// strengths' own scatter, and the location needs two or three corrector solves instead of the ~10
// that a 1e-8 bracket in arclength takes (docs/theory/failure.md 8).
inline constexpr double kOnsetIndexTolerance = 1e-7;

// Fills r.damage from the run's events and points (the onsets' events are renamed
// kDamageOnsetEvent). Nothing for a case without a `damage:` section.
void add_damage_results(const IndentationSetup& setup, PathResult& r);

}  // namespace si
