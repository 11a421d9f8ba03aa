// Gauss-Legendre quadrature on [-1, 1], used to integrate through the thickness of the normal
// line (vam.md 4.1: n >= p + 1 points per element are exact for every integrand of order p).
#pragma once

#include <vector>

namespace si {

struct GaussRule {
  std::vector<double> points;   // abscissae in (-1, 1), ascending
  std::vector<double> weights;  // summing to 2
};

// The n-point rule (n >= 1), exact for polynomials of degree 2n - 1.
GaussRule gauss_legendre(int n);

}  // namespace si
