// Flat plate meshes in the plane z = 0, directors +z (elements counter-clockwise seen from +z).
#pragma once

#include "model/disk_o_grid.hpp"
#include "model/mesh.hpp"

namespace si {

// Rectangle [0, lx] x [0, ly], nx x ny equal elements; node (i, j) has index i + (nx + 1) j.
// Node sets: "edge_x0" (x = 0), "edge_x1" (x = lx), "edge_y0" (y = 0), "edge_y1" (y = ly),
// "edge" (their union), and "center" (the node at (lx/2, ly/2)) when nx and ny are even.
// Used for the Sze cantilever strips (10 x 1, 16 x 1) and the Navier laminate plates.
Mesh rectangular_plate_mesh(double lx, double ly, int nx, int ny);

// The same with node lines at the given stations (strictly increasing, at least 2 each): node
// (i, j) is (xs[i], ys[j], 0). Node sets as above ("edge_x0" at xs.front(), ...); "center" is the
// middle node when both lists have an odd number of stations. For graded meshes
// (graded_stations.hpp).
Mesh rectangular_plate_mesh(const std::vector<double>& xs, const std::vector<double>& ys);

// Disk of the given radius centred at the origin, O-grid with radial grading (disk_o_grid.hpp).
// Node sets: "edge" (the rim), "center" (the node at the origin), and for the quarter model
// (x >= 0, y >= 0) "symmetry_x" (x = 0) and "symmetry_y" (y = 0).
Mesh circular_plate_mesh(double radius, double size_center, double size_edge, double refine_radius,
                         Symmetry symmetry);

// MacNeal & Harder (1985) patch-test mesh: rectangle 0.24 x 0.12, five distorted elements with
// interior nodes (0.04, 0.02), (0.18, 0.03), (0.16, 0.08), (0.08, 0.08) (linear.md, patch
// tests). Nodes 0-3 are the corners (0,0), (0.24,0), (0.24,0.12), (0,0.12), nodes 4-7 the
// interior nodes in the order above; element 0 is the central one.
// Node sets: "boundary" (0-3), "interior" (4-7).
Mesh macneal_harder_patch_mesh();

// Slit annular plate of Sze, Liu & Lo (2004), section 3.3 (nonlinear.md): inner radius
// inner_r, outer radius outer_r, n_radial x n_circ elements, the slit along the positive x
// axis. The slit's two lips are separate, coincident nodes: the lip at angle 0 (its elements
// lie at y > 0) is "slit_fixed", the lip at angle 360 deg (elements at y < 0) is "slit_loaded"
// - the benchmark clamps one lip and lifts the other with a line force q; which is which is
// immaterial by symmetry, this is the convention here. Further sets: "inner_edge",
// "outer_edge", and the corners of the loaded lip "loaded_inner" (r = inner_r; Sze's W_A per
// nonlinear.md) and "loaded_outer" (r = outer_r; W_B). check_mesh must be called with
// allow_coincident_nodes = true for this mesh. The reference mesh is 10 x 80.
Mesh annulus_with_slit_mesh(double inner_r, double outer_r, int n_radial, int n_circ);

}  // namespace si
