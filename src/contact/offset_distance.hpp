// Signed distance to a body that is a convex core offset by a radius r (Minkowski sum with a
// ball): d = |x - p| - r with p the closest core point. Shared by the sphere (core = point),
// cylinder (core = axis segment) and flat punch (core = disc or semi-infinite axis).
#pragma once

#include "core/linalg.hpp"

namespace si {

// `core_curvature` is the derivative of p with respect to x (a projector onto the core's
// tangent directions scaled by their curvature: 0 for a point, a a^T along a line). Then
// n = (x - p)/|x - p| and dn/dx = (I - n n^T - core_curvature)/|x - p|, since n is orthogonal
// to the core's tangents. At x = p the normal is undefined: `fallback` is used and dn/dx = 0.
double offset_distance(const Vector3d& x, const Vector3d& p, double r,
                       const Matrix3d& core_curvature, const Vector3d& fallback, Vector3d* normal,
                       Matrix3d* hessian);

}  // namespace si
