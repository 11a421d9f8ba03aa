#include "material/material_library.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace si {
namespace {

constexpr double kGPa = 1000.0;  // MPa per GPa

struct LibraryEntry {
  const char* name;
  Material (*make)(const char* name);
};

// Strengths in the order X_T, X_C, Y_T, Y_C, Z_T, Z_C, S_12, S_13, S_23 (MPa; 0 = not given)
// and the toughness G_Ic, G_IIc (N/mm; 0 = not given). Sources: docs/materials.md.
struct FailureData {
  double strengths[kStrengthKeys];
  double toughness[kToughnessKeys];
};

Material with_failure_data(const Material& m, const FailureData& d) {
  PlyStrengths s;
  for (int k = 0; k < kStrengthKeys; ++k)
    if (d.strengths[k] > 0) s.set(StrengthKey(k), d.strengths[k]);
  FractureToughness t;
  for (int k = 0; k < kToughnessKeys; ++k)
    if (d.toughness[k] > 0) t.set(ToughnessKey(k), d.toughness[k]);
  return m.with_failure_properties(s, t);
}

// Y_C / (2 tan 53 deg): the transverse shear strength S_23 implied by a fracture plane at 53 deg
// under transverse compression (Puck; Davila, Camanho & Rose, J. Compos. Mater. 39 (2005) 323,
// LaRC03 eq. 12), used where a source gives no S_23.
double transverse_shear_strength(double Y_C) {
  return Y_C / (2.0 * std::tan(53.0 * kPi / 180.0));
}

// A transversely isotropic ply from the in-plane data that prepreg sources publish: E3 = E2,
// G13 = G12, nu13 = nu12 and G23 = E2 / (2 (1 + nu23)).
Material transversely_isotropic(const char* name, double E1, double E2, double G12, double nu12,
                                double nu23) {
  EngineeringConstants c;
  c.E1 = E1;
  c.E2 = c.E3 = E2;
  c.G12 = c.G13 = G12;
  c.G23 = E2 / (2.0 * (1.0 + nu23));
  c.nu12 = c.nu13 = nu12;
  c.nu23 = nu23;
  return Material::orthotropic(name, c);
}

// Source paper, Table 1 (carbon/epoxy ply). G23 = 6 GPa is what the paper prints: with
// E2 = 10 GPa and nu23 = 0.3 a transversely isotropic ply would have G23 = E2/(2(1+nu23))
// = 3.85 GPa, and G13 = 3 GPa differs from G12 = 6 GPa, so this set is NOT transversely
// isotropic. It is kept exactly as printed because the paper's results were computed with it.
// The paper gives no strengths: ASSUMED those of T300/914C (below), the published prepreg
// closest to its elastic constants (E1 138 vs 130, E2 11 vs 10, G12 5.5 vs 6 GPa), and the
// toughness of IM7/8552 (below) for want of a published T300/914C value (docs/materials.md).
Material paper_carbon_epoxy(const char* name) {
  EngineeringConstants c;
  c.E1 = 130 * kGPa;
  c.E2 = 10 * kGPa;
  c.E3 = 10 * kGPa;
  c.G12 = 6 * kGPa;
  c.G13 = 3 * kGPa;
  c.G23 = 6 * kGPa;
  c.nu12 = 0.3;
  c.nu13 = 0.5;
  c.nu23 = 0.3;
  return with_failure_data(
      Material::orthotropic(name, c),
      {{1500, 900, 27, 200, 27, 200, 80, 80, transverse_shear_strength(200)}, {0.277, 0.788}});
}

// IM7/8552 (Hexcel), the values of Camanho, Maimi & Davila, Compos. Sci. Technol. 67 (2007)
// 2715 (E1, E2, G12, nu12, X_T, Y_T, Y_C, S_12) and Camanho et al., Mech. Mater. 59 (2013) 36
// (nu23, X_C, G_Ic, G_IIc), as tabulated in NASA's CompDam_DGD (tests/IM7-8552.props).
// Z_T = Y_T, Z_C = Y_C and S_13 = S_12 by transverse isotropy; S_23 from Y_C (above).
Material im7_8552(const char* name) {
  return with_failure_data(
      transversely_isotropic(name, 171.42 * kGPa, 9.08 * kGPa, 5.29 * kGPa, 0.32, 0.52),
      {{2326.2, 1200.1, 62.3, 199.8, 62.3, 199.8, 92.3, 92.3, transverse_shear_strength(199.8)},
       {0.277, 0.788}});
}

// AS4/3501-6 (Hercules), World-Wide Failure Exercise lamina data: Soden, Hinton & Kaddour,
// Compos. Sci. Technol. 58 (1998) 1011, Table 1 (fibre volume fraction 0.60). No toughness.
Material as4_3501_6(const char* name) {
  return with_failure_data(
      transversely_isotropic(name, 126 * kGPa, 11 * kGPa, 6.6 * kGPa, 0.28, 0.4),
      {{1950, 1480, 48, 200, 48, 200, 79, 79, transverse_shear_strength(200)}, {0, 0}});
}

// T300/BSL914C (Toray fibre, Ciba-Geigy resin), World-Wide Failure Exercise lamina data: Soden,
// Hinton & Kaddour, Compos. Sci. Technol. 58 (1998) 1011, Table 1. No toughness.
Material t300_914c(const char* name) {
  return with_failure_data(
      transversely_isotropic(name, 138 * kGPa, 11 * kGPa, 5.5 * kGPa, 0.28, 0.4),
      {{1500, 900, 27, 200, 27, 200, 80, 80, transverse_shear_strength(200)}, {0, 0}});
}

// Generic structural steel for indenters: E = 210 GPa, nu = 0.3 (Eurocode 3, EN 1993-1-1,
// section 3.2.6).
Material steel(const char* name) {
  return Material::isotropic(name, 210 * kGPa, 0.3);
}

// Aluminium 2024-T3: E = 73.1 GPa, nu = 0.33 (ASM Aerospace Specification Metals data sheet
// for 2024-T3; MMPDS gives 10.5-10.7 Msi, i.e. 72-74 GPa).
Material aluminium_2024_t3(const char* name) {
  return Material::isotropic(name, 73.1 * kGPa, 0.33);
}

// A foam core (Rohacell WF) and a film adhesive (FM 73) were requested for the sandwich study,
// but no manufacturer data sheet values could be verified while writing this library, so they
// are left out rather than guessed; case files can define them inline with cited values.
constexpr LibraryEntry kEntries[] = {
    {"paper-carbon-epoxy", paper_carbon_epoxy},
    {"im7-8552", im7_8552},
    {"as4-3501-6", as4_3501_6},
    {"t300-914c", t300_914c},
    {"steel", steel},
    {"aluminium-2024-t3", aluminium_2024_t3},
};

}  // namespace

std::vector<std::string> library_material_names() {
  std::vector<std::string> names;
  for (const auto& e : kEntries) names.emplace_back(e.name);
  return names;
}

Material library_material(std::string_view name) {
  for (const auto& e : kEntries)
    if (name == e.name) return e.make(e.name);
  std::string known;
  for (const auto& n : library_material_names()) known += (known.empty() ? "" : ", ") + n;
  throw_input("unknown library material (known: " + known + ")",
              Where{"", "", std::string(name), 0});
}

}  // namespace si
