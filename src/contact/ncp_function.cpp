#include "contact/ncp_function.hpp"

#include <cmath>

namespace si {

NcpValue ncp(NcpFunction f, double a, double b) {
  if (f == NcpFunction::kMin) return a > b ? NcpValue{b, 0, 1} : NcpValue{a, 1, 0};
  const double r = std::hypot(a, b);
  if (r == 0) return {0, 1 - M_SQRT1_2, 1 - M_SQRT1_2};
  // a + b - r loses every digit when a >> b > 0 (lambda large, tiny gap); for a + b > 0 the
  // equal form 2ab / (a + b + r) does not.
  const double value = a + b > 0 ? 2 * a * b / (a + b + r) : a + b - r;
  return {value, 1 - a / r, 1 - b / r};
}

}  // namespace si
