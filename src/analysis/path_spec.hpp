// The indentation depth path of a run (docs/case-file.md `path`).
#pragma once

#include <optional>
#include <vector>

namespace si {

enum class PathMethod { kNatural, kPseudoArclength };

// A geometric imperfection seeded from a critical mode (docs/case-file.md `path.imperfection`,
// analysis/imperfection_seed.hpp): the mesh's nodes move by `amplitude` (mm) times mode `mode`
// (1 = the lowest) of the restricted tangent at the perfect path's first stability change,
// scaled so that its largest nodal translation is 1.
struct ImperfectionSpec {
  int mode = 1;
  double amplitude = 0.0;
};
// The modes an imperfection may name: the stability analysis computes this many at most.
inline constexpr int kMaxImperfectionModes = 10;

// Branch switching at the fundamental path's first bifurcation (docs/case-file.md
// `path.branch_switch`, continuation/branch_switching.hpp): the new branch is followed from there,
// along the critical mode's +direction (1) or its other half (-1), until it meets another
// stability change (where it rejoins a branch) or a bound of the depth.
struct BranchSwitchSpec {
  int direction = 1;
};

// The Newton iterations a path step may take before it is cut (analysis/indentation_run.cpp).
inline constexpr int kPathMaxIterations = 25;

// All lengths in mm.
struct PathSpec {
  PathMethod method = PathMethod::kPseudoArclength;
  double depth_max = 10.0;
  double step = 0.1;
  double step_min = 1e-4;      // default: step / 1000
  double step_max = 1.0;       // default: min(10 step, depth_max)
  std::vector<double> depths;  // optional explicit depths to stop at, increasing, <= depth_max
  // The step controller's aim in Newton iterations per step: a step that took fewer grows, one
  // that took more shrinks (continuation/settings.hpp). On fine meshes the contact set gains
  // many nodes per step and Newton takes 4 at small steps, where the default stops growing.
  int target_iterations = 4;
  // The stability of every point (docs/theory/continuation.md 12) and its changes as events;
  // off by default: the run is then exactly the one without it.
  bool stability = false;
  // The onset of geometric nonlinearity is the first depth where the force departs from the
  // linear-kinematics force by this fraction of it (analysis/critical_points.hpp), in (0, 1).
  double nonlinearity_fraction = 0.05;
  std::optional<ImperfectionSpec> imperfection;   // none: the perfect shell
  std::optional<BranchSwitchSpec> branch_switch;  // none: the fundamental path only
};

// The depth grid of a path: `depths`, or step, 2 step, ..., depth_max.
std::vector<double> depth_grid(const PathSpec& path);

}  // namespace si
