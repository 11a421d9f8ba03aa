#include "analysis/damage_results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/indentation_run.hpp"
#include "analysis/path_columns.hpp"
#include "section/clt_section.hpp"

namespace si {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The work at depth h inside the segment from a to b, on path.csv's trapezoidal integration
// (force linear in the depth): impact_energy.hpp's kTrapezoid reversed.
double work_at(const PathPoint& a, const PathPoint& b, double h) {
  const double ha = a.state.depth, hb = b.state.depth;
  const double t = hb != ha ? (h - ha) / (hb - ha) : 0.0;
  const double force = a.state.force + t * (b.state.force - a.state.force);
  return a.work + 0.5 * (a.state.force + force) * (h - ha);
}

// The criterion of a failure-index column, if `monitor` is one of the run's.
std::optional<Criterion> criterion_of(const std::string& monitor,
                                      const std::vector<Criterion>& criteria) {
  for (Criterion c : criteria)
    if (monitor == column_name(failure_column(c))) return c;
  return std::nullopt;
}

std::vector<DamageOnset> onsets(const IndentationSetup& setup, PathResult& r) {
  std::vector<DamageOnset> out;
  const int force = [&] {
    for (std::size_t i = 0; i < r.monitor_names.size(); ++i)
      if (r.monitor_names[i] == column_name(PathColumn::kForce)) return static_cast<int>(i);
    return -1;
  }();
  for (std::size_t i = 0; i < r.events.size(); ++i) {
    cont::Event& e = r.events[i];
    const std::optional<Criterion> c = criterion_of(e.monitor, r.criteria);
    if (e.type != cont::EventType::kZeroCrossing || !c) continue;
    e.name = kDamageOnsetEvent;
    if (e.step < 1 || e.step >= static_cast<int>(r.points.size())) continue;
    DamageOnset o;
    o.criterion = *c;
    o.event = static_cast<int>(i);
    o.depth = e.p;
    o.force = force >= 0 && force < e.monitors.size() ? e.monitors[force] : kNaN;
    o.work = work_at(r.points[e.step - 1], r.points[e.step], e.p);
    // Where it is: at the event's own unknowns, else (a resumed run's events before its
    // checkpoint keep no unknowns) at the point after it.
    const IndentationState at =
        e.x.size() > 0 ? setup.problem->probe_at(e.x) : r.points[e.step].state;
    o.at = at.failure[static_cast<int>(*c)];
    o.located = e.located;
    o.accuracy = e.accuracy;
    out.push_back(o);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const DamageOnset& a, const DamageOnset& b) { return a.depth < b.depth; });
  return out;
}

// Davies-Zhang with the smallest G_IIc of the plies' materials (io/ refused a ply without it),
// D about the mid-surface.
DelaminationThreshold threshold(const Laminate& laminate, const ThresholdSpec& spec) {
  double g = std::numeric_limits<double>::infinity();
  for (const Ply& ply : laminate.plies)
    if (const auto v = ply.material.toughness().get(ToughnessKey::kGIIc)) g = std::min(g, *v);
  Laminate mid = laminate;
  mid.reference_offset = 0;
  return delamination_threshold(d_block(clt_abd(mid)), g, spec.stiffness, spec.delaminations);
}

// The first depth where the path's force reaches `load`, linear between points; NaN if never.
double depth_at_force(const std::vector<PathPoint>& points, double load) {
  for (std::size_t i = 1; i < points.size(); ++i) {
    const IndentationState &a = points[i - 1].state, &b = points[i].state;
    if (a.force < load && b.force >= load)
      return a.depth + (b.depth - a.depth) * (load - a.force) / (b.force - a.force);
  }
  return kNaN;
}

}  // namespace

void add_damage_results(const IndentationSetup& setup, PathResult& r) {
  if (!setup.spec.damage) return;
  const DamageSpec& spec = *setup.spec.damage;
  r.damage.onsets = onsets(setup, r);
  if (spec.threshold) {
    r.damage.threshold = threshold(setup.spec.laminate, *spec.threshold);
    r.damage.threshold_depth = depth_at_force(r.points, r.damage.threshold->load);
  }
  if (r.points.size() < 2) {  // no work done: every energy lies beyond the path
    for (double e : spec.impact_energies) r.damage.energies.push_back({e});
    for (EnergyPoint& e : r.damage.energies) e.depth = e.force = kNaN;
  } else if (!spec.impact_energies.empty()) {
    ForceDepthPath path;
    for (const PathPoint& p : r.points) {
      path.depth.push_back(p.state.depth);
      path.force.push_back(p.state.force);
    }
    r.damage.energies =
        depths_at_energies(path, spec.impact_energies, WorkInterpolation::kTrapezoid);
  }
}

}  // namespace si
