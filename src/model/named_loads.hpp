// Loads on named sets, as a user writes them (docs/case-file.md, `loads`), and their
// translation into Loads (loads.hpp). All values are those of the whole shell:
//  * kPoint: `vector` is the force (N) at each node of the set, or at the node nearest to `at`.
//    In a quarter model a node on one symmetry plane carries half of it, on both a quarter (the
//    share of the whole shell's force that the modelled part carries).
//  * kMoment: `vector` is the moment (N mm) at each node of the set, or at the node nearest to
//    `at` (a NodalMoment, loads.hpp: constant generalised forces on the rotation dofs, the
//    fixed-axis moment of plane bending); shared on symmetry planes as a point force.
//  * kEdge: `vector` is a force per unit length (N/mm) and `moment` a moment per unit length
//    (N mm/mm) on every element side whose two nodes are in the set: consistent nodal forces
//    (loads.hpp LineLoad) and nodal moments (each side of reference length L gives half of m L
//    to each of its nodes, the consistent load of a constant m with linear interpolation).
//    Refused on a symmetry plane.
//  * kPressure: `pressure` (MPa) on the elements of an element set (a physical surface), of the
//    elements whose four nodes are in a node set, or of the whole mesh (`on` empty). A positive
//    pressure acts on the director side and pushes against the directors (as `load.pressure`:
//    inwards on a cap's convex side, towards -z on a plate); `follower` follows the deformed
//    surface.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/loads.hpp"
#include "model/mesh.hpp"

namespace si {

enum class NamedLoadType { kPoint, kMoment, kEdge, kPressure };

struct NamedLoadSpec {
  NamedLoadType type = NamedLoadType::kPoint;
  std::string on;                      // set name; empty: `at` (point) or the whole mesh (pressure)
  std::optional<Vector3d> at;          // kPoint, kMoment: the node nearest to this position (mm)
  Vector3d vector = Vector3d::Zero();  // kPoint: N per node; kMoment: N mm per node; kEdge: N/mm
  Vector3d moment = Vector3d::Zero();  // kEdge: N mm/mm
  double pressure = 0;                 // kPressure, MPa
  bool follower = false;               // kPressure
  Where where;                         // the entry in the case file, for messages
};

// Adds to `loads`. `symmetry_sets` are the node sets on symmetry planes (quarter models).
// Resolving `at` adds the node set "loads[i]" (i the entry's index) to the mesh. Errors carry
// the entry's `where`: an unknown set (listing the available ones), a set without element sides
// (edge), without elements (pressure), an edge on a symmetry plane.
void add_named_loads(Mesh& mesh, const std::vector<NamedLoadSpec>& specs,
                     const std::vector<std::string>& symmetry_sets, Loads& loads);

}  // namespace si
