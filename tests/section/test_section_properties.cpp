// Cross-checks between independent section methods of our own code (vam.md 11.5 item 3 and
// section 10): the VAM zeroth-order stiffness A_R must equal the CLT ABD matrix for plies rotated
// about the normal, for any lay-up and reference surface. (The shear stiffnesses of the three
// methods legitimately differ - by 7 % for G22 of [0]8 - and are each checked against their own
// references in test_vam_section.cpp and test_transverse_shear.cpp.)
#include "section/section_properties.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "material/material_library.hpp"
#include "section/layup_notation.hpp"

namespace si {
namespace {

Laminate make_laminate(const std::string& notation, double offset_fraction) {
  const Material m = library_material("paper-carbon-epoxy");
  Laminate lam;
  for (double a : parse_layup(notation)) lam.plies.push_back(Ply{m, 0.475, a});
  lam.reference_offset = offset_fraction * lam.thickness();
  return lam;
}

TEST(SectionProperties, VamARIsCltForEveryLayupAndReference_VamMd_11_5_3) {
  const std::vector<std::string> layups = {
      "[0/0]2S",    "[15/-15]2S", "[30/-30]2S", "[45/-45]2S",    "[60/-60]2S",   "[75/-75]2S",
      "[90/-90]2S", "[0/90]2S",   "[0/90]",     "[30/-30/0/90]", "[0/+-45/90]s", "[15/60/-20]"};
  for (const auto& l : layups) {
    for (double f : {0.0, -0.5, 0.5, 0.17}) {
      const auto s = analyze_section(make_laminate(l, f), l);
      const double scale = s.clt_abd.cwiseAbs().maxCoeff();
      // 1e-12 relative (vam.md 11.5 item 3); the entries span h^2/12 ~ 1 in mm, so the max
      // entry is the natural scale.
      EXPECT_LE((s.vam.A_R - s.clt_abd).cwiseAbs().maxCoeff(), 1e-12 * scale)
          << l << " reference offset " << f << " h";
    }
  }
}

TEST(SectionProperties, RejectsInvalidLaminate) {
  Laminate empty;
  EXPECT_THROW(analyze_section(empty, "empty"), Error);
}

}  // namespace
}  // namespace si
