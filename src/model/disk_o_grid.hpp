// The quadrilateral "O-grid" (butterfly) mesh of a flat, radially graded disk, shared by the
// circular plate and, mapped onto the sphere, by the spherical cap.
//
// A square block centred on the axis is surrounded by radial blocks that map its sides to the
// circle, so no element degenerates at the centre (a polar grid would put triangles there) and
// the centre is always a node. Per quarter: an n x n square [0,a]^2 and two n x m radial blocks
// (one per 45-degree sector); the full disk is four rotated quarters. The corner of the square
// joins three elements with 90/135/135 degree angles.
//
// Grading: the target element size is size_center up to refine_radius from the centre, then
// grows linearly to size_edge at the rim (size_center <= size_edge is required: the grid has no
// tangential coarsening, so it refines towards the centre only). The number n of tangential
// divisions per 45-degree sector is the smallest that makes the tangential size (pi r / 4n) at
// most size_center at refine_radius and at most size_edge at the rim. Radial stations
// equidistribute the target size along the sector's middle line (other radial lines are scaled
// copies); the radial size is also capped at 4 times the local tangential size, so a very
// coarse size_edge gives more rings rather than elongated elements. The square's half-side is
// n * size_center, capped at half the radius.
#pragma once

#include "model/mesh.hpp"
#include "model/symmetry.hpp"

namespace si {

struct DiskGrading {
  double radius = 0;         // mm
  double size_center = 0;    // mm, target element size within refine_radius
  double size_edge = 0;      // mm, target element size at the rim
  double refine_radius = 0;  // mm, 0 <= refine_radius; beyond the radius the mesh is uniform
};

// Throws an input error unless sizes and radii are positive and finite, the sizes are at most
// the radius and size_center <= size_edge.
void validate(const DiskGrading& grading);

// The disk in the plane z = 0 centred at the origin; node 0 is the centre. Nodes on the axes
// have exactly zero coordinates, nodes on the rim are at exactly `radius` (to round-off).
// Directors +z; node sets are left to the caller.
Mesh disk_o_grid(const DiskGrading& grading, Symmetry symmetry);

// For a quarter model, the node sets "symmetry_x" (nodes on x = 0) and "symmetry_y" (y = 0).
// The O-grid places those nodes exactly on the planes, so the test is exact.
void add_symmetry_node_sets(Mesh& mesh, Symmetry symmetry);

}  // namespace si
