// The laminate's contact face as an elastic surface over the shell (`contact.local: anisotropic`
// with `local_support: shell`; docs/theory/local-indentation.md 6.10): a force f at one point of
// the face moves the face at distance r, relative to the shell's own (Reissner-Mindlin)
// deflection, by C(r) f, the influence coefficients of a boundary-element contact (Johnson,
// Contact Mechanics, 1985, 5.9; Kalker 1990) with the section's own kernel. Per wave of
// wavenumber k the face's excess compliance is C(k) = H_inf (1 + kappa(k h)) (support_kernel.hpp,
// kShell: the exact plate's top face less the Reissner-Mindlin plate, without the Poisson term
// of bending, averaged over the wave's direction), so that
//     C(r) = (1 / 2 pi) int_0^inf C(k) J0(k r) dk
//          = H_inf / (2 pi) [1 / r + (1 / h) int_0^inf kappa(x) J0(x r / h) dx]:
// Boussinesq's 1 / (pi E* r) of the top ply's half-space near the force, less the plate's shear
// deflection (kappa ~ t1 / x, t1 = -h <1 / e.G.e> / H_inf), taken by hankel_j0.hpp. A force spread
// evenly over a disc of radius b moves the disc's centre by
//     C_b = (2 / b^2) int_0^b r C(r) dr = H_inf / (pi b^2) [b + h int_0^{b/h} rho F(rho) d rho],
// F the transform of kappa: the coefficient of a node on itself. Of the mid-plane kernel
// (PlateSurface::kMid: H_mid - H_RM, which vanishes at short waves but for the shear term) the
// same without Boussinesq's term: C(r) = H_inf / (2 pi h) int (1 + kappa) J0 dx.
#pragma once

#include <memory>

#include "contact/hankel_j0.hpp"
#include "contact/support_kernel.hpp"

namespace si {

class FaceInfluence {
 public:
  // kernel: of a kShell support. r_max: the largest distance asked, mm.
  FaceInfluence(std::shared_ptr<const SupportKernel> kernel, double r_max);

  double thickness() const { return h_; }
  double r_max() const { return transform_.rho_max() * h_; }
  // C(r), mm/N, 0 < r <= r_max.
  double point(double r) const;
  // C_b, mm/N: the centre of a disc of radius b (mm, 0 < b <= r_max) under a unit force.
  double disc(double b) const;

 private:
  std::shared_ptr<const SupportKernel> kernel_;
  double h_ = 0, far_ = 0;
  double boussinesq_ = 1;  // the 1/r term's weight: 1 for the top face, 0 for the mid-plane
  HankelJ0 transform_;
};

// The tail of kShell's kappa, kappa = t1 / x + t3 / x^3 + O(x^-5): t1 from the shear stiffness,
// t3 from kappa at x = 2000 (the far field's closed forms, no transfer matrices).
struct KappaTail {
  double t1 = 0, t3 = 0;
};
KappaTail shell_kappa_tail(const SupportKernel& kernel);

}  // namespace si
