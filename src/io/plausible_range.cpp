#include "io/plausible_range.hpp"

#include <cmath>

namespace si {

void check_plausible(double value, const PlausibleRange& range, const Where& where) {
  const double magnitude = std::abs(value);
  if (value == 0.0 || (magnitude >= range.min && magnitude <= range.max)) return;
  throw_input(format_quantity(value, range.dimension) + " is not a plausible value for " +
                  range.what +
                  " (accepted magnitudes: " + format_quantity(range.min, range.dimension) + " to " +
                  format_quantity(range.max, range.dimension) + "); check the unit",
              where);
}

}  // namespace si
