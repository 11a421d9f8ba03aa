// What supports the face under the indenter in a finite-thickness local contact law, and the
// normalised surface compliance of that support (docs/theory/local-indentation.md 6.3-6.4):
//  * kBondedBase, kFrictionlessBase: the stack `layers` (the upper half of the laminate) on a
//    rigid base, bonded or frictionless (layer_compliance.hpp);
//  * kPlate: the whole laminate as a free plate, its top face relative to its mid-plane (the
//    shell's reference surface), without the Poisson thickness change of plate bending:
//        H_loc = H_top - H_mid + (c2 / x) / (1 + D x^2 / (G h^2)),   c2 = I h / D,
//    I = int_0^{h/2} nu(z) z dz the top face's rise per unit bending curvature along e
//    (nu = [C_tt^-1 C_tp v]_33, the ply's thickness strain per in-plane strain v = e e under plane
//    stress), D the cylindrical bending stiffness along e (classical laminate theory, symmetric
//    laminates) and G = e.G.e the shell's transverse shear stiffness. The Poisson term is global
//    (it follows the shell's curvature, the F-bar term of the paper's interpolated contact): at
//    long waves, where H_top - H_mid -> -c2/x, it is removed exactly; the factor 1/(1 + ...), the
//    share of bending in a Reissner-Mindlin plate's deflection at that wavelength, hands it back
//    to the exact solution at short waves, where it is no longer a plate-bending term.
//  * kShell: the same face against the shell's own Reissner-Mindlin plate instead of the exact
//    mid-plane, H_loc = H_top - H_RM + (L / x) / (1 + D x^2 / (G h^2))
//    (reissner_mindlin_compliance.hpp): what the shell lacks at its face, for the non-local
//    contact of contact/face_influence.hpp. At long waves H_top - H_RM = -L / x + O(x), L twice
//    the top face's Poisson rise over the thickness average (the rise, and the curvature the
//    face load makes by reciprocity: what the F-bar rows carry, contact.fbar), removed as for
//    kPlate, so H_loc -> 0; at short waves H_RM ~ 1 / (k e.G.e) and kappa decays like -1/x.
// For each, with x = k h (h the stack's thickness) and H(x, phi) + H_i (H_i = 2 (1 - nu_i^2)/E_i
// of an elastic indenter, 0 for a rigid one),
//     kappa(x) = <H(x, phi) + H_i>_phi / H_inf - 1,    H_inf = <H_top layer(phi)>_phi + H_i,
// the half-space compliance of the top layer (anisotropic_half_space.hpp): kappa(0) = -1 (a
// finite stack under a long-wave load is stiff), kappa(inf) = 0 (the top layer's half-space).
// The angular average is Vlassak & Nix's circular-contact approximation (6.2). kappa is kept as
// a Chebyshev series in xi, x = L (1 + xi) / (1 - xi) (a smooth map of [0, inf) to [-1, 1)), and
// the contact problem's kernel K(y) = int_0^inf kappa(x) cos(x y) dx as a Chebyshev series on
// [0, y_max], sampled for cubic Hermite interpolation on a grid of 1/200 (error ~1e-12 K).
#pragma once

#include <vector>

#include "contact/local_support.hpp"
#include "core/chebyshev.hpp"
#include "core/linalg.hpp"
#include "section/homogenised_stiffness.hpp"

namespace si {

// kShell: which of the exact plate's surfaces the kernel is of (the face the indenter meets, or
// the mid-plane, for the laminate's mid-surface deflection beside the shell's).
enum class PlateSurface { kTop, kMid };

struct SupportSpec {
  LocalSupport support = LocalSupport::kBondedBase;  // not kHalfSpace: no kernel for it
  std::vector<LayerStiffness> layers;                // bottom first
  double indenter_compliance = 0;                    // H_i, 1/MPa
  Matrix2d shear_stiffness = Matrix2d::Zero();       // kPlate, kShell: the section's G, N/mm
  Matrix3d bending_stiffness = Matrix3d::Zero();     // kShell: its D, N mm (H_RM)
  PlateSurface surface = PlateSurface::kTop;         // kShell
};

// The composite Gauss-Legendre rule on [0, x_max] the kernel's integrals use, with kappa there.
struct KernelQuadrature {
  std::vector<double> x, weight, kappa;
};

class SupportKernel {
 public:
  // y_max: the largest argument of cosine_transform (twice the largest contact radius / h).
  // directions: angles of the average over [0, pi). Throws an input si::Error for an empty
  // stack, kHalfSpace, or kPlate without a positive-definite shear stiffness.
  SupportKernel(const SupportSpec& spec, double y_max, int directions = 8);

  const SupportSpec& spec() const { return spec_; }
  int directions() const { return directions_; }
  double thickness() const { return thickness_; }
  double far_compliance() const { return far_compliance_; }
  double kappa(double x) const;
  // kappa from the transfer matrices at x > 0, without the series (for the tests).
  double kappa_direct(double x) const;
  double cosine_transform(double y) const;
  // The rule on [0, x_max] with panels of `panel` and 8 points each.
  KernelQuadrature quadrature(double x_max, double panel) const;

 private:
  double mean_compliance(double x) const;    // <H(x, phi) + H_i>_phi
  double shell_long_wave(double phi) const;  // kShell: L of H_top - H_RM = -L / x + O(x)
  SupportSpec spec_;
  int directions_;
  double thickness_ = 0, far_compliance_ = 0;
  double far_field_ = 0;  // x beyond which the top layer's half-space is the face's compliance
  std::vector<double> poisson_c2_, bending_ratio_;  // per direction: c2 (kShell: L), D / (G h^2)
  ChebyshevSeries kappa_;                           // in xi
  // K(y) at y_j = j dy with K'(y_j), from its Chebyshev series, for cubic Hermite interpolation
  // (the contact solutions evaluate K ~1e5 times: Clenshaw's 160 terms would dominate).
  double transform_step_ = 0;
  std::vector<double> transform_, transform_slope_;
};

}  // namespace si
