#include "io/force_travel.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/indentation_run.hpp"
#include "core/error.hpp"

namespace si {
namespace {

// The force of the point at depth d; NaN if the path has none there.
double force_at(const PathResult& r, double d) {
  for (const PathPoint& p : r.points)
    if (std::abs(p.state.depth - d) <= 1e-9 * (1 + d)) return p.state.force;
  return std::nan("");
}

// The path section that stops at the travels and ends at the last one.
void stop_at(PathSpec& path, const std::vector<double>& travels) {
  path.method = PathMethod::kNatural;
  path.depth_max = travels.back();
  path.depths.clear();
  for (double t : travels)
    if (t > 0.0) path.depths.push_back(t);
  path.step = std::min(path.step, path.depth_max);
  path.step_max = std::max(path.step, std::min(path.step_max, path.depth_max));
  path.step_min = std::min(path.step_min, path.step);
}

}  // namespace

ForceTravel run_force_travel(CaseFile c, const std::vector<double>& travels, int threads,
                             const std::function<bool()>& keep_going) {
  ForceTravel out;
  if (travels.empty() || !(travels.back() > 0.0)) {
    out.failure = "no travel to run to";
    return out;
  }
  stop_at(c.path, travels);
  try {
    IndentationSetup setup(std::move(c), threads);
    const PathCallback go_on = [&](const PathPoint&, const cont::Vector&) {
      return !keep_going || keep_going();
    };
    const PathResult r = run_indentation_path(setup, go_on);
    out.path_points = static_cast<int>(r.points.size());
    for (double t : travels) out.force.push_back(force_at(r, t));  // travel 0: the first touch
    out.ok =
        std::all_of(out.force.begin(), out.force.end(), [](double f) { return std::isfinite(f); });
    if (!out.ok)
      out.failure = "the path stopped at travel " +
                    std::to_string(r.points.empty() ? 0.0 : r.points.back().state.depth) +
                    " mm, before " + std::to_string(travels.back()) + " mm" +
                    (r.reason.empty() ? "" : ": " + r.reason);
  } catch (const Error& e) {
    out.failure = e.what();
  }
  return out;
}

}  // namespace si
