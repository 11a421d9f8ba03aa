// Derivatives of smooth nodal fields at a point by a least-squares polynomial fit over the nearest
// nodes: what the 3-D stress recovery needs from a shell model (R and its first, second and third
// in-plane derivatives, section/through_thickness_recovery.hpp), which the elements themselves do
// not provide (bilinear elements have piecewise-constant first and no higher derivatives).
//
// A generalisation of Zienkiewicz & Zhu's superconvergent patch recovery (IJNME 33 (1992) 1331):
// they fit a polynomial to the superconvergent Gauss-point values of the elements around a node;
// here a complete polynomial of degree p in the in-plane coordinates is fitted to nodal values
// (e.g. the element-averaged nodal strains of analysis/nodal_resultants.hpp) at the n nodes nearest
// to the point, and differentiated there. The coordinates are centred on the point and scaled by
// the patch radius, so the least-squares system is well conditioned for any mesh size. On a curved
// shell the caller passes coordinates in the tangent plane at the point.
#pragma once

#include <array>
#include <vector>

#include "core/linalg.hpp"

namespace si {

struct PatchFit {
  Eigen::VectorXd value;              // one entry per field (column of the nodal values)
  std::array<Eigen::VectorXd, 2> d1;  // ,1 ,2
  std::array<Eigen::VectorXd, 3> d2;  // ,11 ,12 ,22
  std::array<Eigen::VectorXd, 4> d3;  // ,111 ,112 ,122 ,222 (zero for degree < 3)
  int nodes = 0;                      // nodes used
  double radius = 0;                  // distance of the farthest node used
};

// `points` (one per node) and `values` (one row per node, one column per field). Uses the
// max(nodes, 2 * terms) nearest nodes, terms = (degree + 1)(degree + 2)/2. Throws an input
// si::Error for a degree outside 1..4, mismatched sizes, too few nodes, or a patch whose nodes do
// not determine the polynomial (all on a line, for instance).
PatchFit fit_patch(const std::vector<Vector2d>& points, const Eigen::MatrixXd& values,
                   const Vector2d& at, int degree, int nodes = 0);

}  // namespace si
