// The indenter a case asks for (docs/case-file.md `indenter`; indenter_factory.hpp builds it).
#pragma once

#include <optional>

#include "core/linalg.hpp"
#include "material/material.hpp"

namespace si {

enum class IndenterShape { kSphere, kSuperquadric, kFlatPunch, kCylinder };

// A rigid indenter unless `material` is given. Which fields are used depends on `shape`.
struct IndenterSpec {
  IndenterShape shape = IndenterShape::kSphere;
  double radius = 12.7;        // mm, sphere, flat punch, cylinder
  double edge_radius = 0;      // mm, flat punch: rounding of the punch edge (0 = sharp)
  double length = 0;           // mm, cylinder: axial length
  double a = 0, b = 0, c = 0;  // mm, superquadric semi-axes along x1, x2, x3
  // Superquadric exponents (Barr 1981): (|x/a|^(2/e2) + |y/b|^(2/e2))^(e2/e1) + |z/c|^(2/e1) = 1;
  // e1 = e2 = 1 is an ellipsoid, smaller values are boxier. 0 < e <= 2 keeps it convex.
  double e1 = 1, e2 = 1;
  std::optional<Material> material;  // empty: rigid
  // Pose (indenter.hpp IndenterPose). Position of the reference point (sphere, super-quadric and
  // cylinder centre, flat-punch tip) at travel 0, mm; empty: on the apex normal, clear of the
  // shell. The depth is the travel after first touch, found automatically.
  std::optional<Vector3d> position;
  Vector3d direction{0, 0, -1};  // direction of travel (normalised when read)
  Vector3d axis{0, 1, 0};        // cylinder axis
};

}  // namespace si
