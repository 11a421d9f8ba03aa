#include "shell/shape4.hpp"

namespace si {

Shape4 evaluate_shape4(ShapeSet set, double xi, double eta) {
  // Both sets are products f(1 + xi_I xi) f(1 + eta_I eta) / c with f(s) = s^p.
  const int p = set == ShapeSet::kBilinear ? 1 : 3;
  const double c = set == ShapeSet::kBilinear ? 4 : 64;
  auto power = [](double s, int n) { return n == 1 ? s : s * s * s; };
  auto dpower = [](double s, int n) { return n == 1 ? 1 : 3 * s * s; };
  Shape4 out;
  for (int i = 0; i < 4; ++i) {
    const double a = 1 + kCornerXi[i] * xi;
    const double b = 1 + kCornerEta[i] * eta;
    out.N(i) = power(a, p) * power(b, p) / c;
    out.N_xi(i) = kCornerXi[i] * dpower(a, p) * power(b, p) / c;
    out.N_eta(i) = kCornerEta[i] * power(a, p) * dpower(b, p) / c;
  }
  return out;
}

}  // namespace si
