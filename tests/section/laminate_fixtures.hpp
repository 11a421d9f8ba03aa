// Materials and lay-ups shared by the section tests.
#pragma once

#include <vector>

#include "material/material.hpp"
#include "section/laminate.hpp"

namespace si::testing {

// Indentation-paper material of vam.md section 12 (MPa): E1 = 130, E2 = E3 = 10, G12 = 6,
// G23 = 6, G13 = 3 GPa; nu12 = 0.3, nu23 = 0.3, nu13 = 0.5. Plies are 0.475 mm.
inline Material paper_material() {
  EngineeringConstants c;
  c.E1 = 130000;
  c.E2 = c.E3 = 10000;
  c.G12 = 6000;
  c.G23 = 6000;
  c.G13 = 3000;
  c.nu12 = 0.3;
  c.nu23 = 0.3;
  c.nu13 = 0.5;
  return Material::orthotropic("paper", c);
}
constexpr double kPaperPly = 0.475;  // mm

// Pagano (1969) material of vam.md section 11.3 with E_T = 1: E_L/E_T = 25, G_LT/E_T = 0.5,
// G_TT/E_T = 0.2, nu = 0.25 for all pairs; E3 = E_T, G13 = G_LT, G23 = G_TT.
inline Material pagano_material() {
  EngineeringConstants c;
  c.E1 = 25;
  c.E2 = c.E3 = 1;
  c.G12 = c.G13 = 0.5;
  c.G23 = 0.2;
  c.nu12 = c.nu13 = c.nu23 = 0.25;
  return Material::orthotropic("pagano", c);
}

// Plies of one material and thickness, angles listed bottom to top, mid-surface reference.
inline Laminate make_laminate(const Material& material, double ply_thickness,
                              const std::vector<double>& angles_deg) {
  Laminate laminate;
  for (double angle : angles_deg) laminate.plies.push_back(Ply{material, ply_thickness, angle});
  return laminate;
}

// Lay-up notation helpers: [a/b]2S = a b a b | b a b a.
inline std::vector<double> repeat(const std::vector<double>& angles, int times) {
  std::vector<double> out;
  for (int i = 0; i < times; ++i) out.insert(out.end(), angles.begin(), angles.end());
  return out;
}
inline std::vector<double> symmetric(const std::vector<double>& half) {
  std::vector<double> out = half;
  out.insert(out.end(), half.rbegin(), half.rend());
  return out;
}

// Largest absolute entry, the scale for relative matrix comparisons.
template <typename M>
double max_abs(const M& m) {
  return m.cwiseAbs().maxCoeff();
}

}  // namespace si::testing
