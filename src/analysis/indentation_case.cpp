#include "analysis/indentation_case.hpp"

namespace si {

std::vector<Criterion> monitored_criteria(const IndentationCase& c) {
  return c.damage ? c.damage->criteria : std::vector<Criterion>{};
}

double contact_face_offset(const IndentationCase& c) {
  const double top = 0.5 * c.laminate.thickness() - c.laminate.reference_offset;
  return c.contact.surface == ContactSurface::kOuter ? top : -c.laminate.reference_offset;
}

double back_face_offset(const IndentationCase& c) {
  return -0.5 * c.laminate.thickness() - c.laminate.reference_offset;
}

}  // namespace si
