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
  // Olsson's closed form (header). The form sqrt(D11 D22)(A + 1)/2 used before issue 16's last
  // stage is not the impedance mean: 27 % off at A = 2.3.
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
