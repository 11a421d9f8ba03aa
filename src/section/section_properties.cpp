#include "section/section_properties.hpp"

#include <utility>

#include "section/clt_section.hpp"
#include "section/transverse_shear.hpp"

namespace si {

SectionProperties analyze_section(const Laminate& laminate, std::string label,
                                  const VamOptions& options) {
  laminate.validate();
  SectionProperties out{std::move(label),
                        laminate,
                        clt_abd(laminate),
                        fsdt_shear_stiffness(laminate),
                        equilibrium_shear_stiffness(laminate),
                        analyze_vam(laminate, options)};
  return out;
}

}  // namespace si
