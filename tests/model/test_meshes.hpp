// Small structured meshes for the model-layer tests (the real generators live in src/model/mesh*
// and are written in parallel).
#pragma once

#include <cmath>
#include <string>

#include "model/mesh.hpp"

namespace si::testing {

// nx x ny quads on [0, lx] x [0, ly] in the plane z = 0, directors +e_z, counter-clockwise.
// Node sets: "left" (x = 0), "right" (x = lx), "bottom" (y = 0), "top" (y = ly), "all",
// "corner" (node at the origin), "far_corner" (lx, ly).
inline Mesh square_plate(int nx, int ny, double lx = 1.0, double ly = 1.0) {
  Mesh m;
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.nodes.emplace_back(lx * i / nx, ly * j / ny, 0.0);
      m.directors.emplace_back(0.0, 0.0, 1.0);
      const int n = id(i, j);
      if (i == 0) m.node_sets["left"].push_back(n);
      if (i == nx) m.node_sets["right"].push_back(n);
      if (j == 0) m.node_sets["bottom"].push_back(n);
      if (j == ny) m.node_sets["top"].push_back(n);
      m.node_sets["all"].push_back(n);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      m.elements.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  m.node_sets["corner"] = {id(0, 0)};
  m.node_sets["far_corner"] = {id(nx, ny)};
  return m;
}

// The plate lifted onto a sphere of radius R centred at (0, 0, -R) (apex at the origin) with
// radial directors: a quarter cap whose "left" and "bottom" sets lie on the x = 0 and y = 0 planes.
inline Mesh quarter_cap(int n, double a, double R) {
  Mesh m = square_plate(n, n, a, a);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    Vector3d& p = m.nodes[i];
    p.z() = std::sqrt(R * R - p.x() * p.x() - p.y() * p.y());
    m.directors[i] = p.normalized();
    p.z() -= R;
  }
  return m;
}

}  // namespace si::testing
