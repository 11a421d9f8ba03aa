// Quarter of the MacNeal-Harder pinched hemisphere with an 18-degree hole at the pole
// (MacNeal & Harder 1985; linear.md, "Pinched hemisphere"): the part x >= 0, y >= 0 of the
// sphere of the given radius centred at the origin, between the equator (z = 0) and the hole
// edge at 18 deg from the pole (+z), i.e. latitude 0 to 72 deg.
//
// n x n elements: n along the azimuth (x axis to y axis) and n along the latitude; all nodes on
// the sphere, directors the exact outward normals (elements counter-clockwise seen from
// outside).
//
// Node sets: "symmetry_x" (plane x = 0), "symmetry_y" (plane y = 0), "hole_edge", "equator",
// "load_x" (the equator node on the x axis, (R, 0, 0)) and "load_y" ((0, R, 0)).
#pragma once

#include "model/mesh.hpp"

namespace si {

Mesh hemisphere_mesh(double radius, int n);

}  // namespace si
