#include "section/gauss_legendre.hpp"

#include <cmath>

#include "core/error.hpp"

namespace si {

// Newton iteration on P_n from the Tricomi-type initial guess cos(pi (i + 3/4) / (n + 1/2));
// n is at most a dozen here, so the three-term recurrence is accurate to round-off.
GaussRule gauss_legendre(int n) {
  SI_REQUIRE(n >= 1, "a Gauss-Legendre rule needs at least one point");
  const double pi = std::acos(-1.0);
  GaussRule rule;
  rule.points.assign(n, 0.0);
  rule.weights.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);  // P_n' from P_n and P_{n-1}
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule.points[n - 1 - i] = x;  // the guesses descend; store ascending
    rule.weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return rule;
}

}  // namespace si
