#include "analysis/companion_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.hpp"

namespace si {
namespace {

// Depths are landed on to round-off; a point matches a companion point within this.
bool same_depth(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a));
}

}  // namespace

IndentationCase companion_case(const IndentationCase& c, const PathResult& r) {
  std::vector<double> depths;
  for (const PathPoint& p : r.points)
    if (p.branch == 0 && p.state.depth > 0) depths.push_back(p.state.depth);
  std::sort(depths.begin(), depths.end());
  depths.erase(std::unique(depths.begin(), depths.end(), same_depth), depths.end());
  SI_ASSERT(!depths.empty());
  IndentationCase out = c;
  out.mesh.size_apex *= kCompanionCoarsening;
  out.mesh.size_edge *= kCompanionCoarsening;
  out.mesh.error_estimate = ErrorEstimate::kRecovery;
  out.mesh.tolerance = 0;
  out.path.depths = depths;
  out.path.depth_max = depths.back();
  out.path.stability = false;
  out.path.branch_switch.reset();
  out.damage.reset();
  return out;
}

void attach_force_errors(PathResult& r, const PathResult& companion) {
  const double richardson = std::pow(kCompanionCoarsening, kCompanionOrder) - 1;
  for (PathPoint& p : r.points) {
    p.force_error = std::nan("");
    if (p.branch != 0 || p.state.force == 0) continue;
    const auto twin =
        std::find_if(companion.points.begin(), companion.points.end(),
                     [&](const PathPoint& q) { return same_depth(q.state.depth, p.state.depth); });
    if (twin == companion.points.end()) continue;
    p.force_error =
        std::abs(p.state.force - twin->state.force) / (richardson * std::abs(p.state.force));
  }
  r.companion_mesh = true;
}

CompanionRun run_companion(const IndentationCase& c, PathResult& r, int threads,
                           const std::function<void(const CompanionRun&)>& announce,
                           const PathCallback& on_point) {
  CompanionRun out;
  if (std::none_of(r.points.begin(), r.points.end(),
                   [](const PathPoint& p) { return p.branch == 0 && p.state.depth > 0; })) {
    out.why_not = "the run has no point at a positive depth";
    return out;
  }
  std::optional<IndentationSetup> companion;
  try {
    companion.emplace(companion_case(c, r), threads);
  } catch (const Error& e) {
    out.why_not = std::string("its mesh cannot be built: ") + e.what();
    return out;
  }
  out.shell_unknowns = companion->problem->num_shell_unknowns();
  out.depth_max = companion->spec.path.depth_max;
  if (announce) announce(out);
  PathControl control;
  control.critical_points = false;  // its force only
  out.path = run_indentation_path(*companion, on_point, control);
  attach_force_errors(r, out.path);
  return out;
}

const PathPoint* largest_force_error(const PathResult& r) {
  const PathPoint* worst = nullptr;
  for (const PathPoint& p : r.points)
    if (!std::isnan(p.force_error) && (!worst || p.force_error > worst->force_error)) worst = &p;
  return worst;
}

}  // namespace si
