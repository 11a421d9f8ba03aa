#include "contact/ncp_function.hpp"

#include <cmath>

namespace si {
namespace {

NcpValue min_function(double a, double b) {
  return a > b ? NcpValue{b, 0, 1} : NcpValue{a, 1, 0};
}

NcpValue fischer_burmeister(double a, double b) {
  const double r = std::hypot(a, b);
  if (r == 0) return {0, 1 - M_SQRT1_2, 1 - M_SQRT1_2};
  // a + b - r loses every digit when a >> b > 0 (lambda large, tiny gap); for a + b > 0 the
  // equal form 2ab / (a + b + r) does not.
  const double value = a + b > 0 ? 2 * a * b / (a + b + r) : a + b - r;
  return {value, 1 - a / r, 1 - b / r};
}

}  // namespace

NcpValue ncp(NcpFunction f, double a, double b) {
  switch (f) {
    case NcpFunction::kMin:
      return min_function(a, b);
    case NcpFunction::kFischerBurmeisterMin:
      return a < 0 || b < 0 ? min_function(a, b) : fischer_burmeister(a, b);
    case NcpFunction::kFischerBurmeister:
      break;
  }
  return fischer_burmeister(a, b);
}

}  // namespace si
