#include "section/homogenised_stiffness.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "material/ply_rotation.hpp"

namespace si {
namespace {

// Voigt positions of the in-plane strains [e11, e22, g12] and the out-of-plane stresses
// [s33, s23, s13].
constexpr int kInPlane[3] = {0, 1, 5};
constexpr int kOutOfPlane[3] = {2, 3, 4};

Matrix3d block(const Matrix6d& M, const int (&rows)[3], const int (&cols)[3]) {
  Matrix3d b;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b(i, j) = M(rows[i], cols[j]);
  return b;
}

void set_block(Matrix6d& M, const int (&rows)[3], const int (&cols)[3], const Matrix3d& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M(rows[i], cols[j]) = b(i, j);
}

// The mixed matrix [s_p ; e_t] = F [e_p ; s_t] of a stiffness (the header's equation), in the
// order [p, t] of its rows and columns.
Matrix6d mixed_matrix(const Matrix6d& C) {
  const Matrix3d Cpp = block(C, kInPlane, kInPlane), Cpt = block(C, kInPlane, kOutOfPlane);
  const Matrix3d Ctp = block(C, kOutOfPlane, kInPlane);
  const Matrix3d Ctt_inv = block(C, kOutOfPlane, kOutOfPlane).inverse();
  Matrix6d F;
  F.topLeftCorner<3, 3>() = Cpp - Cpt * Ctt_inv * Ctp;
  F.topRightCorner<3, 3>() = Cpt * Ctt_inv;
  F.bottomLeftCorner<3, 3>() = -Ctt_inv * Ctp;
  F.bottomRightCorner<3, 3>() = Ctt_inv;
  return F;
}

Matrix6d stiffness_of_mixed(const Matrix6d& F) {
  const Matrix3d Ctt = F.bottomRightCorner<3, 3>().inverse();
  const Matrix3d Ctp = -Ctt * F.bottomLeftCorner<3, 3>();
  const Matrix3d Cpt = F.topRightCorner<3, 3>() * Ctt;
  const Matrix3d Cpp = F.topLeftCorner<3, 3>() - Cpt * F.bottomLeftCorner<3, 3>();
  Matrix6d C;
  set_block(C, kInPlane, kInPlane, Cpp);
  set_block(C, kInPlane, kOutOfPlane, Cpt);
  set_block(C, kOutOfPlane, kInPlane, Ctp);
  set_block(C, kOutOfPlane, kOutOfPlane, Ctt);
  return C;
}

}  // namespace

std::vector<LayerStiffness> laminate_layers(const Laminate& laminate, double z_bottom,
                                            double z_top) {
  const std::vector<double> z = laminate.interfaces();
  SI_REQUIRE(z.front() <= z_bottom && z_bottom < z_top && z_top <= z.back(),
             "laminate_layers: the slice must lie within the laminate, bottom below top");
  std::vector<LayerStiffness> layers;
  for (std::size_t k = 0; k < laminate.plies.size(); ++k) {
    const double t = std::min(z[k + 1], z_top) - std::max(z[k], z_bottom);
    if (t <= 0) continue;
    const Ply& ply = laminate.plies[k];
    layers.push_back({rotate_stiffness_voigt(ply.material.stiffness(), ply.angle_deg), t});
  }
  return layers;
}

Matrix6d homogenised_stiffness(const std::vector<LayerStiffness>& layers) {
  SI_REQUIRE(!layers.empty(), "homogenised_stiffness: no layers");
  Matrix6d F = Matrix6d::Zero();
  double total = 0;
  for (const LayerStiffness& l : layers) {
    SI_REQUIRE(l.thickness > 0, "homogenised_stiffness: a layer thickness is not positive");
    F += l.thickness * mixed_matrix(l.C);
    total += l.thickness;
  }
  const Matrix6d C = stiffness_of_mixed(F / total);
  return (C + C.transpose()) / 2;  // symmetric to roundoff
}

}  // namespace si
