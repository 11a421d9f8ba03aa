// What a run computes about damage onset along its path (docs/case-file.md `damage`,
// docs/theory/failure.md 6): the failure criteria monitored at the nodes near the indenter, the
// stress recovery they read, the closed-form delamination threshold and the depths at given
// impact energies. io/case_file.cpp reads the case file's `damage:` section into it; a case
// without the section has no DamageSpec and its run is exactly the one without damage.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/linalg.hpp"
#include "damage/delamination_threshold.hpp"
#include "damage/failure_index.hpp"

namespace si {

// How the 3-D ply stresses are recovered from the shell's strains
// (section/through_thickness_recovery.hpp): the first-order VAM recovery from R and its first
// derivatives, or with the zig-zag refinement and the equilibrium shear from the second and
// third derivatives (Pagano-verified, docs/theory/failure.md 3).
enum class StressRecovery { kFirstOrder, kRefined };

// The contacted face's pressure the recovery reads (docs/theory/failure.md 7): Hertz's
// p0 sqrt(1 - r^2/a^2) carrying the indenter's force over the larger of Hertz's contact radius
// (the local law's, or the laminate's anisotropic half-space) and the shell model's own patch,
// or each contact node's multiplier over its tributary area (the mesh's pressure: onsets that
// read it scale with the apex element's area).
enum class FacePressure { kHertz, kNodal };

// A point where the recovered stresses and indices are reported (and monitored): the mesh node
// nearest to `position`. The apex is always one (name "apex").
struct DamagePoint {
  std::string name;
  Vector3d position = Vector3d::Zero();  // mm, global
};

// Davies & Zhang's threshold with the effective stiffness and the number of delaminations
// (damage/delamination_threshold.hpp); G_IIc is the smallest of the plies' materials.
struct ThresholdSpec {
  EffectiveBendingStiffness stiffness = EffectiveBendingStiffness::kOlsson;
  int delaminations = 1;
};

struct DamageSpec {
  std::vector<Criterion> criteria;  // monitored, one result column each; distinct
  std::vector<DamagePoint> points;  // besides the apex
  StressRecovery recovery = StressRecovery::kRefined;
  FacePressure face_pressure = FacePressure::kHertz;
  // The strains' patch fit at a node takes every node within this distance (mm), and at least
  // the 25 nearest: shell resultants near a concentrated load mean something on the scale of
  // the thickness, and a fit over a fixed length converges with the mesh where one over a fixed
  // number of nodes follows the load's singularity. Negative: twice the laminate's thickness
  // (the smallest multiple with which every criterion's onset on the paper's cap converges,
  // docs/theory/failure.md 7); 0: the 25 nearest nodes only.
  double patch_radius = -1;
  // Nodes monitored: those within `radius` mm of the apex's line of travel; 0 = the contact
  // candidates (the nodes the indenter can reach within the path), the apex and the points.
  double radius = 0;
  std::vector<double> impact_energies;  // N mm
  std::optional<ThresholdSpec> threshold;
};

}  // namespace si
