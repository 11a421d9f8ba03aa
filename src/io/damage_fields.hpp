// Damage output of a run with criteria (docs/results.md "Damage"): per-ply failure-index fields
// in the VTU frames and the recovered stresses and indices at the reported points (the apex and
// `damage.points`) in damage_points.csv, both at the monitored nodes only (analysis/damage_probe:
// the recovery runs near the indenter, nowhere else).
#pragma once

#include <string>

#include "analysis/indentation_run.hpp"
#include "io/vtu_writer.hpp"

namespace si {

// Point data "<criterion>_index_ply<k>" (k = 1 bottom ply; components: bottom, middle, top of the
// ply) for the ply criteria and "delamination_index_interface<k>" (between plies k and k+1),
// zero away from the monitored nodes. `state`: the point's state (its contact pressures).
void add_damage_fields(const IndentationSetup& setup, const IndentationState& state,
                       const cont::Vector& z, VtuFields& fields);

// damage_points.csv's header, and its rows of one converged point: per reported point, per
// recovered point through the thickness (bottom, middle, top of every ply), the stresses in the
// laminate axes and each criterion's index there (interface criteria: on the interface rows,
// the bottom of the ply above, and the top of the ply below).
std::string damage_points_header(const IndentationSetup& setup);
std::string damage_points_rows(const IndentationSetup& setup, const PathPoint& point,
                               const cont::Vector& z);

}  // namespace si
