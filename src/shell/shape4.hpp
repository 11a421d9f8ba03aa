// Shape-function sets of the 4-node shell elements, nodes at the corners (xi, eta) =
// (-1,-1), (1,-1), (1,1), (-1,1) (counterclockwise; shell_element.hpp).
//   kBilinear:  N_I = (1 + xi_I xi)(1 + eta_I eta) / 4 (partition of unity; mitc4).
//   kBernstein: N_I = (1 + xi_I xi)^3 (1 + eta_I eta)^3 / 64, the source paper's eqs 68-71. The
//     paper numbers them in tensor order (its N3 sits at (-1,1), N4 at (1,1)); here they follow the
//     counterclockwise numbering above, the functions are the same. They are NOT a partition of
//     unity: the sum is 1 at the corners but 4/64 at the centre (paper-notes.md, item 1).
#pragma once

#include <Eigen/Dense>

namespace si {

enum class ShapeSet { kBilinear, kBernstein };

struct Shape4 {
  Eigen::Vector4d N;
  Eigen::Vector4d N_xi;   // dN/dxi
  Eigen::Vector4d N_eta;  // dN/deta
};

constexpr double kCornerXi[4] = {-1, 1, 1, -1};
constexpr double kCornerEta[4] = {-1, -1, 1, 1};

Shape4 evaluate_shape4(ShapeSet set, double xi, double eta);

}  // namespace si
