// The force's discretisation error of a run, estimated from a companion run on a coarser mesh
// (mesh.error_estimate: companion; docs/theory/discretisation-error.md 4): the same case with every
// element size doubled, landing on the run's own depths, and at each depth Richardson's estimate
// of the run's error from the two forces,
//     |F_h - F*| ~ |F_h - F_2h| / (2^p - 1),   p = 2,
// the order of a force (a reaction: a functional of the displacement) of bilinear elements. The
// force at a contact converges unevenly while a node ring enters the contact between two depths,
// so a single point's estimate scatters about its true error; the largest over the path is the
// run's statement (measured on the paper's cap in the document above).
#pragma once

#include <functional>
#include <string>

#include "analysis/indentation_run.hpp"

namespace si {

// The companion's element sizes over the run's.
inline constexpr double kCompanionCoarsening = 2.0;
// The error's assumed order in the element size.
inline constexpr double kCompanionOrder = 2.0;

// The companion's case: the same shell, indenter, contact and kinematics on the mesh with
// size_apex and size_edge times kCompanionCoarsening (refine_radius kept), landing on the depths
// of the run's points on its fundamental branch (path.depths), without what does not bear on the
// force (stability, damage, branch switching, its own companion). The run must have a point at a
// positive depth.
IndentationCase companion_case(const IndentationCase& c, const PathResult& r);

// Sets every point's force_error from the companion's force at the same depth (NaN where the
// companion has no point there, where the force is zero, or on a switched branch), and
// r.companion_mesh.
void attach_force_errors(PathResult& r, const PathResult& companion);

// What run_companion did: its path (empty when there was none: `why_not` says why), its size and
// the deepest depth it lands on.
struct CompanionRun {
  PathResult path;
  int shell_unknowns = 0;
  double depth_max = 0;  // mm
  std::string why_not;
};

// mesh.error_estimate: companion: builds companion_case(c, r), runs it (on_point as for any path:
// false stops it) and attaches its errors to r. A run without a point at a positive depth has no
// companion (why_not). A companion that cannot be built or stops early
// leaves the points it has no depth for without an estimate; r's own points are unchanged
// otherwise. `announce` is called once the companion is built, before it runs.
CompanionRun run_companion(const IndentationCase& c, PathResult& r, int threads,
                           const std::function<void(const CompanionRun&)>& announce = {},
                           const PathCallback& on_point = {});

// The point with the largest force_error (nullptr if none has one).
const PathPoint* largest_force_error(const PathResult& r);

}  // namespace si
