// Everything users ask of a laminate section, computed once: the CLT ABD matrix, the three
// transverse-shear stiffnesses (VAM, FSDT with k = 5/6, equilibrium/energy-consistent) and the
// VAM Reissner-Mindlin law with its load coupling. Orderings as in vam.md: Yu order
// R = [e11, 2e12, e22, k11, k12+k21, k22], gamma = [2g13, 2g23].
#pragma once

#include <string>

#include "core/linalg.hpp"
#include "section/laminate.hpp"
#include "section/vam_section.hpp"

namespace si {

struct SectionProperties {
  std::string label;  // lay-up notation or a description of an explicit ply list
  Laminate laminate;
  Matrix6d clt_abd;        // CLT [A B; B D] about the reference surface
  Matrix2d G_fsdt;         // k = 5/6
  Matrix2d G_equilibrium;  // Whitney-type, from the equilibrium shear-stress profiles
  VamSection vam;          // A_R, G, F-bar, c_L and fit diagnostics
};

SectionProperties analyze_section(const Laminate& laminate, std::string label,
                                  const VamOptions& options = {});

}  // namespace si
