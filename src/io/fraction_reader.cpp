#include "io/fraction_reader.hpp"

#include "core/units.hpp"

namespace si {

double read_fraction(const std::string& text, const Where& where) {
  const bool percent = !text.empty() && text.back() == '%';
  double number = 0;
  try {
    number = parse_quantity(percent ? text.substr(0, text.size() - 1) : text,
                            Dimension::kDimensionless) /
             (percent ? 100.0 : 1.0);
  } catch (const Error& e) {
    throw e.within(where);
  }
  if (!(number > 0 && number < 1))
    throw_input("expected a fraction in (0, 1), e.g. 0.05 or 5 %", where);
  return number;
}

double fraction_or(const MapReader& map, const std::string& key, double fallback) {
  return map.has(key) ? read_fraction(map.scalar(key), map.where(key)) : fallback;
}

}  // namespace si
