// Quadrilateral mesh of a spherical cap, the application case of the source paper (paper-notes
// P8: base chord diameter 50 mm, R = 80.9 mm, t = 3.8 mm, clamped edge, graded mesh denser
// near the apex).
//
// Geometry: z is the axis of the cap and points to its convex side. The base circle (radius
// base_radius) lies in the plane z = 0 and the apex is at (0, 0, H), H = R - sqrt(R^2 - c^2)
// the rise; the sphere's centre is at (0, 0, H - R). Directors are the exact outward unit
// normals (p - centre) / R, pointing up at the apex, towards an indenter coming from +z.
//
// The mesh is the disk O-grid of disk_o_grid.hpp laid out in geodesic polar coordinates: a
// point at distance s from the axis of the flat grid goes to the point of the sphere at arc
// length s from the apex, in the same azimuth. Element sizes therefore hold on the surface; all
// nodes lie on the sphere.
//
// Node sets:
//   "edge"        nodes on the base circle (z = 0)
//   "apex"        the single node at the apex
//   "symmetry_x"  (quarter model only) nodes on the plane x = 0
//   "symmetry_y"  (quarter model only) nodes on the plane y = 0
#pragma once

#include "model/disk_o_grid.hpp"
#include "model/mesh.hpp"

namespace si {

struct SphericalCapMeshSpec {
  using Symmetry = si::Symmetry;

  double base_radius = 25;  // mm, radius of the base circle (half the chord)
  double sphere_radius = 80.9;
  double size_apex = 0.5;     // mm, target element size within refine_radius (arc length)
  double size_edge = 2;       // mm, target element size at the base circle
  double refine_radius = 13;  // mm, arc length from the apex
  Symmetry symmetry = Symmetry::kFull;
};

// Rise of the cap, R - sqrt(R^2 - c^2).
double cap_height(const SphericalCapMeshSpec& spec);

// Throws an input error naming the field for non-positive sizes or a base radius not smaller
// than the sphere radius (the cap must be less than a hemisphere).
void validate(const SphericalCapMeshSpec& spec);

// The validated mesh (check_mesh passes).
Mesh spherical_cap_mesh(const SphericalCapMeshSpec& spec);

}  // namespace si
