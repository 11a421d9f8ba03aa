// The refined zone of a built-in mesh sized from the contact (issue 19 item 2): where the case
// does not set mesh.refine_radius, the zone is the plan radius within which the undeformed
// indenter at depth_max would cut the undeformed contact face. The contact radius stays inside
// it as long as both bodies move away from each other under the contact (the gap there is the
// undeformed gap minus the depth plus both deflections, so it can close only where the undeformed
// gap is below the depth): on the paper's cap the contact radius is 0.37 of it at 2 mm and 0.61
// at 10 mm (docs/theory/discretisation-error.md 5).
#pragma once

#include "analysis/indentation_case.hpp"

namespace si {

// The plan radius (mm) within which the indenter at `depth` (mm along its travel, from first
// touch at the apex) intersects the undeformed contact face, the indenter taken along its widest
// plan direction and the face's curvature along its flattest (a cap's sphere; flat for plates and
// a cylindrical panel). Capped at the indenter's own plan extent.
double indenter_reach(const IndentationCase& c, double depth);

// `c` with mesh.refine_radius set to max(indenter_reach(c, depth_max), 4 size_apex) when the
// case leaves it open and builds its mesh (not with mesh.file); otherwise `c` unchanged.
IndentationCase with_refine_zone(IndentationCase c);

}  // namespace si
