// Cylindrical panels: Scordelis-Lo roof, Sze's hinged roof, pinched cylinder (linear.md,
// nonlinear.md).
//
// Geometry (the Scordelis-Lo convention of linear.md): the cylinder's axis is the y axis, z is
// vertical and the crown is the line x = 0, z = radius. A point at angle theta from the crown
// (towards +x) and axial position y is (R sin theta, y, R cos theta). Directors are the exact
// outward normals (sin theta, 0, cos theta); n_circ elements span the angle, n_axial the length.
//
// PanelPart::kFull spans theta in [-half_angle, half_angle] and y in [-length/2, length/2]: the
// panel is centred on the origin's vertical line. PanelPart::kQuarter keeps theta >= 0, y >= 0
// (the quarter model with symmetry at the crown and at the axial mid-plane).
//
// Node sets (present for both parts unless noted):
//   "curved_ends"     the curved edges y = +-length/2 (kQuarter: y = length/2), e.g. the
//                     Scordelis-Lo diaphragms
//   "straight_edges"  the straight edges theta = +-half_angle (kQuarter: theta = half_angle),
//                     free in Scordelis-Lo, hinged in Sze's roof
//   "axial_midplane"  nodes at y = 0 (a boundary of the quarter model)
//   "crown"           nodes at theta = 0 (a boundary of the quarter model)
//   "center"          the node at theta = 0, y = 0 (Sze's roof: load point)
//   "free_edge_mid"   the node at theta = half_angle, y = 0 (Scordelis-Lo output point)
// kFull needs even n_axial and n_circ (so that the mid-lines are node lines).
#pragma once

#include "model/mesh.hpp"

namespace si {

enum class PanelPart { kFull, kQuarter };

Mesh cylindrical_panel_mesh(double radius, double length, double half_angle_deg, int n_axial,
                            int n_circ, PanelPart part = PanelPart::kFull);

// The same with node lines at the given stations: angles theta (rad, from the crown) and axial
// positions y, strictly increasing. kFull needs lists symmetric about 0 with an odd number of
// stations (0 is then the middle one), kQuarter lists starting at 0. For graded meshes
// (graded_stations.hpp).
Mesh cylindrical_panel_mesh(double radius, const std::vector<double>& thetas,
                            const std::vector<double>& ys, PanelPart part);

// Octant of the pinched cylinder (linear.md: R = 300, L = 600): the quarter panel with
// half-angle 90 deg and length L, i.e. theta in [0, 90] deg from the top (x = 0, z = R) to the
// side (z = 0), y from the load section (y = 0) to the diaphragm (y = L/2). Besides the panel's
// sets: "diaphragm" (y = L/2), "symmetry_x" (x = 0), "symmetry_y" (y = 0), "symmetry_z" (z = 0)
// and "load" (the node (0, 0, R), where the quarter of the pinching load P acts).
Mesh pinched_cylinder_octant_mesh(double radius, double length, int n_axial, int n_circ);

}  // namespace si
