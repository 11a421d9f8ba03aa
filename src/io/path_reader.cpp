#include "io/path_reader.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "core/units.hpp"
#include "io/fraction_reader.hpp"
#include "io/output_reader.hpp"
#include "io/spellings.hpp"

namespace si {
namespace {

// path.imperfection: {mode: N, amplitude: length}. The mode comes from the stability analysis,
// so the path must ask for it; the amplitude is a length > 0 (a negative one is the same mode's
// other sign: the mode's sign is fixed, its largest translation positive).
ImperfectionSpec read_imperfection(const MapReader& path, bool stability) {
  const MapReader map(path.at("imperfection"), path.where("imperfection"));
  if (!stability)
    throw_input(
        "an imperfection is seeded from a critical mode of the stability analysis: set "
        "`path.stability: true` (and `contact.local: none`)",
        path.where("imperfection"));
  map.allow_only({"mode", "amplitude"});
  ImperfectionSpec s;
  s.mode = map.integer_or("mode", s.mode);
  if (s.mode < 1 || s.mode > kMaxImperfectionModes)
    throw_input("mode " + std::to_string(s.mode) +
                    " is beyond the modes the stability analysis "
                    "computes: give 1 (the lowest) to " +
                    std::to_string(kMaxImperfectionModes),
                map.where("mode"));
  s.amplitude = map.positive("amplitude", Dimension::kLength);
  return s;
}

// path.branch_switch: {direction: 1 | -1}. The bifurcation is found by the stability analysis and
// the new branch needs the arclength (it may turn in depth); an imperfect shell has no
// bifurcation to switch at.
BranchSwitchSpec read_branch_switch(const MapReader& path, const PathSpec& spec) {
  const MapReader map(path.at("branch_switch"), path.where("branch_switch"));
  if (!spec.stability)
    throw_input(
        "branching needs the bifurcation that the stability analysis locates: set "
        "`path.stability: true` (and `contact.local: none`)",
        path.where("branch_switch"));
  if (spec.method != PathMethod::kPseudoArclength)
    throw_input("the new branch is followed by its arclength: set `path.method: pseudo_arclength`",
                path.where("branch_switch"));
  if (spec.imperfection)
    throw_input(
        "an imperfect shell has no bifurcation to switch at: give `imperfection` or "
        "`branch_switch`, not both",
        path.where("branch_switch"));
  map.allow_only({"direction"});
  BranchSwitchSpec s;
  s.direction = map.integer_or("direction", s.direction);
  if (s.direction != 1 && s.direction != -1)
    throw_input("give 1 (along the critical mode) or -1 (the branch's other half)",
                map.where("direction"));
  return s;
}

}  // namespace

// A local contact law's approach and compliant rows are no constraint on the shell alone: the
// restricted tangent (docs/theory/continuation.md 12) is defined without one.
PathSpec read_path(const MapReader& top, const ContactSpec& contact) {
  PathSpec path;
  if (!top.has("path")) return path;
  const MapReader map(top.at("path"), top.where("path"));
  map.allow_only({"method", "depth_max", "step", "step_min", "step_max", "target_iterations",
                  "depths", "stability", "nonlinearity_fraction", "imperfection", "branch_switch"});
  path.method = map.choice_or("method", path_method_spellings(), path.method);
  path.depth_max = map.positive_or("depth_max", Dimension::kLength, path.depth_max);
  path.step = map.positive_or("step", Dimension::kLength, path.step);
  if (path.step > path.depth_max) {
    // Point at what the user wrote: a short depth_max can clash with the default step.
    throw_input("step (" + format_quantity(path.step, Dimension::kLength) +
                    ") exceeds depth_max (" + format_quantity(path.depth_max, Dimension::kLength) +
                    ")",
                map.where(map.has("step") ? "step" : "depth_max"));
  }
  path.step_min = map.positive_or("step_min", Dimension::kLength, path.step / 1000.0);
  path.step_max =
      map.positive_or("step_max", Dimension::kLength, std::min(10.0 * path.step, path.depth_max));
  if (path.step_min > path.step_max)
    throw_input(
        "step_min exceeds step_max (" + format_quantity(path.step_max, Dimension::kLength) + ")",
        map.where("step_min"));
  if (path.step < path.step_min || path.step > path.step_max)
    throw_input("step must lie in [step_min, step_max] = [" +
                    format_quantity(path.step_min, Dimension::kLength) + ", " +
                    format_quantity(path.step_max, Dimension::kLength) + "]",
                map.where("step"));
  path.target_iterations = map.integer_or("target_iterations", path.target_iterations);
  if (path.target_iterations < 2 || path.target_iterations > kPathMaxIterations)
    throw_input("target_iterations must lie in [2, " + std::to_string(kPathMaxIterations) +
                    "] (the Newton iterations a step may take)",
                map.where("target_iterations"));
  if (map.has("depths")) path.depths = read_depth_list(map, "depths", path.depth_max);
  path.stability = map.choice_or("stability", boolean_spellings(), path.stability);
  if (path.stability && contact.local != LocalContactModel::kNone)
    throw_input(
        "the stability of a point is defined without a local contact law (its approach is no "
        "constraint on the shell); set `contact.local: none` or `stability: false`",
        map.where("stability"));
  path.nonlinearity_fraction = fraction_or(map, "nonlinearity_fraction", 0.05);
  if (map.has("imperfection")) path.imperfection = read_imperfection(map, path.stability);
  if (map.has("branch_switch")) path.branch_switch = read_branch_switch(map, path);
  return path;
}

}  // namespace si
