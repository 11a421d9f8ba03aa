#include "material/material_library.hpp"

#include "core/error.hpp"

namespace si {
namespace {

constexpr double kGPa = 1000.0;  // MPa per GPa

struct LibraryEntry {
  const char* name;
  Material (*make)(const char* name);
};

// Source paper, Table 1 (carbon/epoxy ply). G23 = 6 GPa is what the paper prints: with
// E2 = 10 GPa and nu23 = 0.3 a transversely isotropic ply would have G23 = E2/(2(1+nu23))
// = 3.85 GPa, and G13 = 3 GPa differs from G12 = 6 GPa, so this set is NOT transversely
// isotropic. It is kept exactly as printed because the paper's results were computed with it.
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
  return Material::orthotropic(name, c);
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
