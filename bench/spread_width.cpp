// How wide a load must be spread for the Reissner-Mindlin plate of a section to deflect as the
// exact (3-D, Stroh) plate's mid-plane does under a Hertz patch on its top face: issue 20,
// docs/theory/local-indentation.md 6.7. Not a benchmark: a measurement, never in ctest.
//
//   build-bench/bench/spread_width CASE.yaml [a_mm ...]
//
// For the case's laminate, on a flat infinite plate, with the compliances averaged over the
// direction of the wave: H_mid(k) of the free plate loaded on its top face
// (contact/layer_compliance.hpp) and H_RM(k) of the Reissner-Mindlin plate of the section (VAM's
// D and G, bending-twisting kept), both as displacement k / pressure. The centre deflection per
// newton under Hertz's pressure of radius a is (1/2 pi) int p^(k a) H(k) dk, p^(x) = 3 (sin x - x
// cos x) / x^3, the bending part cut at k = 2 pi / 50 mm (a cap of 50 mm: the spreading moves the
// bending deflection by a few 1e-3 only). Prints the excess of the Reissner-Mindlin plate over
// the exact one and the width w for which the Reissner-Mindlin plate under a Hertz patch of
// radius (a^2 + w^2)^0.5 has the exact plate's deflection (bisection); and the smallest, over the
// short waves k t > 2, of H_top - H_RM: the exact face's compliance less the shell's own, the
// kernel a non-local face compliance on the contact rows would use (at long waves it holds the
// Poisson thickening of bending, -c2 / (k t) of local-indentation.md 6.4, negative, which the
// F-bar rows carry instead).
#include <cmath>
#include <cstdio>
#include <vector>

#include "contact/layer_compliance.hpp"
#include "contact/reissner_mindlin_compliance.hpp"
#include "core/constants.hpp"
#include "io/case_file.hpp"
#include "section/homogenised_stiffness.hpp"
#include "section/vam_section.hpp"

namespace {

using si::kPi;

double hertz_transform(double x) {
  return x < 1e-4 ? 1 - x * x / 10 : 3 * (std::sin(x) - x * std::cos(x)) / (x * x * x);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: spread_width CASE.yaml [a_mm ...]\n");
    return 2;
  }
  const si::CaseFile c = si::read_case_file(argv[1]);
  std::vector<double> radii;
  for (int i = 2; i < argc; ++i) radii.push_back(std::atof(argv[i]));
  if (radii.empty()) radii = {0.8, 1.2, 1.6};
  const double h = c.laminate.thickness();
  const auto layers = si::laminate_layers(c.laminate, -h / 2, h / 2);
  const si::VamSection v = si::analyze_vam(c.laminate);
  const Eigen::Matrix3d D = v.A_R.block<3, 3>(3, 3);  // rows k11, k12 + k21, k22
  const int directions = 16;
  std::vector<double> ks, h_rm, h_mid;
  double kernel_min = 1e300, kernel_min_k = 0;
  for (double lk = std::log(2 * kPi / 50); lk < std::log(60 / h); lk += 0.01) {
    const double k = std::exp(lk);
    double rm = 0, mid = 0;
    for (int j = 0; j < directions; ++j) {
      const double phi = (j + 0.5) * kPi / directions;
      const si::PlateFaceCompliance exact = si::plate_face_compliance(layers, phi, k);
      const double shell = si::reissner_mindlin_compliance(D, v.G, phi, k);
      mid += exact.mid / directions;
      rm += shell / directions;
      if (k * h > 2 && exact.top - shell < kernel_min) {
        kernel_min = exact.top - shell;
        kernel_min_k = k;
      }
    }
    ks.push_back(k);
    h_rm.push_back(rm);
    h_mid.push_back(mid);
  }
  const auto centre = [&](double a, const std::vector<double>& H) {
    double s = 0;
    for (std::size_t i = 1; i < ks.size(); ++i)
      s += 0.5 * (hertz_transform(ks[i] * a) * H[i] + hertz_transform(ks[i - 1] * a) * H[i - 1]) *
           (ks[i] - ks[i - 1]);
    return s / (2 * kPi);
  };
  std::printf("%s: t = %.4g mm; per newton under Hertz's pressure of radius a:\n", argv[1], h);
  for (double a : radii) {
    const double exact = centre(a, h_mid);
    double lo = 0, hi = 5 * h;
    for (int it = 0; it < 60; ++it) {
      const double w = 0.5 * (lo + hi);
      (centre(std::sqrt(a * a + w * w), h_rm) > exact ? lo : hi) = w;
    }
    std::printf(
        "  a = %.3g mm: exact %.5e, Reissner-Mindlin %.5e mm/N (excess %.4e); spread width "
        "w = %.4g mm\n",
        a, exact, centre(a, h_rm), centre(a, h_rm) - exact, 0.5 * (lo + hi));
  }
  std::printf("  smallest H_top - H_RM over k t > 2, every direction: %.4e 1/MPa at k t = %.3g\n",
              kernel_min, kernel_min_k * h);
  return 0;
}
