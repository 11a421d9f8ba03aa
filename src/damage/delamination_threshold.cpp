#include "damage/delamination_threshold.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace si {

DelaminationThreshold delamination_threshold(const Matrix3d& D, double G_IIc,
                                             EffectiveBendingStiffness stiffness,
                                             int delaminations) {
  if (!(G_IIc > 0) || !std::isfinite(G_IIc))
    throw_input("the delamination threshold needs G_IIc > 0",
                Where{"", "G_IIc", std::to_string(G_IIc), 0});
  if (delaminations < 1)
    throw_input("the delamination threshold needs at least one delamination",
                Where{"", "delaminations", std::to_string(delaminations), 0});
  DelaminationThreshold out;
  out.D11 = D(0, 0);
  out.D66 = D(1, 1);
  out.D12 = D(0, 2);
  out.D22 = D(2, 2);
  if (!(out.D11 > 0 && out.D22 > 0))
    throw_input("the delamination threshold needs a positive bending stiffness D11, D22");
  const double mean = std::sqrt(out.D11 * out.D22);
  out.anisotropy = (out.D12 + 2 * out.D66) / mean;
  // Olsson's D* = sqrt(D11 D22 (A + 1)/2) (Compos. Part A 32 (2001) 1207, after AIAA J. 30
  // (1992) 1587): the isotropic plate with the point-load impedance 8 sqrt(m D*) of the specially
  // orthotropic infinite plate, whose exact D* is the angular mean D*^(-1/2) = (2/pi)
  // int_0^(pi/2) (D11 c^4 + 2 (D12 + 2 D66) c^2 s^2 + D22 s^4)^(-1/2); the closed form is that mean
  // to 1.5 % for 0.1 <= A <= 3 and exact at A = 1 (tests/damage/test_delamination_threshold.cpp).
  // (The form sqrt(D11 D22)(A + 1)/2 used before issue 16's last stage is 27 % off at A = 2.3.)
  out.D_effective = stiffness == EffectiveBendingStiffness::kOlsson
                        ? mean * std::sqrt((out.anisotropy + 1) / 2)
                        : mean;
  out.G_IIc = G_IIc;
  out.delaminations = delaminations;
  out.stiffness = stiffness;
  const double pi = std::acos(-1.0);
  out.load = pi * std::sqrt(32 * out.D_effective * G_IIc / (delaminations + 2));
  return out;
}

}  // namespace si
