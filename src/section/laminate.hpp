// A laminate: plies listed from the bottom face (x3 = -h/2) to the top face (x3 = +h/2), the
// same order as Abaqus' composite lay-ups and as lay-up notation is read (first = bottom).
// The normal x3 points from the bottom ply to the top ply; the shell's outer face is the top.
//
// The reference surface of the 2-D model sits at x3 = reference_offset, measured from the
// mid-surface (0 = mid-surface, -h/2 = bottom face, +h/2 = top face). Section analyses always
// work about the mid-surface and shift A_R afterwards (vam.md section 6.5).
#pragma once

#include <string>
#include <vector>

#include "core/linalg.hpp"
#include "material/material.hpp"

namespace si {

struct Ply {
  Material material;
  double thickness = 0;  // mm
  double angle_deg = 0;  // fibre angle from x1 towards x2 (see material/ply_rotation.hpp)

  // 3-D stiffness in plate axes, Yu order [11, 12, 22, 13, 23, 33], MPa.
  Matrix6d stiffness_yu() const;
};

struct Laminate {
  std::vector<Ply> plies;       // bottom to top
  double reference_offset = 0;  // mm, position of the 2-D reference surface above the mid-surface

  double thickness() const;
  // Ply interface coordinates measured from the mid-surface: z_0 = -h/2 < z_1 < ... < z_N = h/2.
  std::vector<double> interfaces() const;
  // Index of the ply that contains x3 (measured from the mid-surface); at an interface, the ply
  // above it unless x3 is the top face.
  int ply_at(double x3) const;

  // Throws an input si::Error if there are no plies, a thickness is not positive and finite, or
  // the reference surface lies outside the laminate.
  void validate() const;
};

}  // namespace si
