// The 3-D stress recovery (vam.md 8) against Pagano's exact 3-D elasticity solution of a simply
// supported square [0/90/0] plate under a sinusoidal load (Pagano, J. Compos. Mater. 4 (1970)
// 20-34), driven by the exact Navier solution of our own Reissner-Mindlin plate (VAM A_R, G,
// Fbar), so that only the recovery is measured.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <vector>

#include "core/constants.hpp"
#include "laminate_fixtures.hpp"
#include "navier_rm_plate.hpp"
#include "pagano_plate.hpp"
#include "section/through_thickness_recovery.hpp"
#include "section/transverse_shear.hpp"

namespace si {
namespace {

using testing::NavierRmPlate;
using testing::PaganoPlate;

Laminate pagano_layup() {
  return testing::make_laminate(testing::pagano_material(), 1.0 / 3.0, {0, 90, 0});
}

// Pagano (1970) for the square [0/90/0] plate, as reproduced in Reddy's "Mechanics of Laminated
// Composite Plates and Shells" (2004) tables of the sinusoidally loaded cross-ply plate:
// sigma_x(a/2, b/2, h/2)/(q S^2), sigma_y(a/2, b/2, h/6)/(q S^2), tau_xz(0, b/2, 0)/(q S),
// tau_yz(a/2, 0, 0)/(q S), tau_xy(0, 0, h/2)/(q S^2). Three printed digits; tau_xy is printed at
// both faces (0.0289/0.0288 at S = 10, 0.0213/0.0214 at S = 100), so it is checked to 1.2e-4.
struct PublishedPagano {
  double S, sx, sy, txz, tyz, txy;
};
constexpr PublishedPagano kPublished[] = {
    {4, 0.801, 0.534, 0.256, 0.2172, 0.0511},
    {10, 0.590, 0.285, 0.357, 0.1228, 0.0289},
    {100, 0.539, 0.181, 0.395, 0.0828, 0.0213},
};

TEST(PaganoExact, SquareCrossPly_0_90_0_ReproducesPublishedStresses) {
  for (const PublishedPagano& ref : kPublished) {
    const double h = 1, a = ref.S * h, q0 = 1;
    const PaganoPlate plate(pagano_layup(), a, a, q0);
    const double s2 = ref.S * ref.S;
    const double sx = std::abs(plate.at(h / 2).sigma_xx) / s2;
    const double sy = std::abs(plate.at(h / 6, 1).sigma_yy) / s2;
    const double txz = std::abs(plate.at(0).tau_xz) / ref.S;
    const double tyz = std::abs(plate.at(0).tau_yz) / ref.S;
    const double txy = std::abs(plate.at(h / 2).tau_xy) / s2;
    std::printf(
        "S = %g: sx %.4f (%.3f) sy %.4f (%.3f) txz %.4f (%.3f) tyz %.4f (%.4f) txy %.4f (%.4f)\n",
        ref.S, sx, ref.sx, sy, ref.sy, txz, ref.txz, tyz, ref.tyz, txy, ref.txy);
    EXPECT_NEAR(sx, ref.sx, 6e-4);
    EXPECT_NEAR(sy, ref.sy, 6e-4);
    EXPECT_NEAR(txz, ref.txz, 6e-4);
    EXPECT_NEAR(tyz, ref.tyz, 6e-5);
    EXPECT_NEAR(txy, ref.txy, 1.2e-4);
  }
}

// The thickness averages of Pagano's displacements as 2-D amplitudes [U, V, W, B1, B2]:
// u = <U>/h, w = <W>/h and the rotation of the best-fit straight normal, beta = 12 <z U>/h^3.
Eigen::Matrix<double, 5, 1> exact_plate_amplitudes(const Laminate& laminate, double a) {
  const PaganoPlate plate(laminate, a, a, 1.0);
  const std::vector<double> z = laminate.interfaces();
  const double h = z.back() - z.front();
  Eigen::Matrix<double, 5, 1> x = Eigen::Matrix<double, 5, 1>::Zero();
  for (int k = 0; k + 1 < static_cast<int>(z.size()); ++k) {
    constexpr int n = 400;  // midpoint rule on a smooth profile: relative error ~1e-6
    for (int i = 0; i < n; ++i) {
      const double zi = z[k] + (z[k + 1] - z[k]) * (i + 0.5) / n, w = (z[k + 1] - z[k]) / n;
      const testing::PaganoPoint p = plate.at(zi, k);
      x += w * (Eigen::Matrix<double, 5, 1>() << p.u / h, p.v / h, p.w / h,
                12 * zi * p.u / (h * h * h), 12 * zi * p.v / (h * h * h))
                   .finished();
    }
  }
  return x;
}

// Peak magnitudes through the thickness of each stress component at its Pagano point.
struct Peaks {
  double sx, sy, txy, txz, tyz;
};

// z samples: every ply on a fine grid with both faces.
template <class F>
double peak_over_z(const Laminate& laminate, F stress_at) {
  const std::vector<double> z = laminate.interfaces();
  double peak = 0;
  for (int k = 0; k + 1 < static_cast<int>(z.size()); ++k)
    for (int i = 0; i <= 60; ++i)
      peak = std::max(peak, std::abs(stress_at(k, z[k] + (z[k + 1] - z[k]) * i / 60.0)));
  return peak;
}

Peaks exact_peaks(const Laminate& laminate, double a) {
  const PaganoPlate plate(laminate, a, a, 1.0);
  auto peak = [&](double testing::PaganoPoint::*member) {
    return peak_over_z(laminate, [&](int k, double z) { return plate.at(z, k).*member; });
  };
  return {peak(&testing::PaganoPoint::sigma_xx), peak(&testing::PaganoPoint::sigma_yy),
          peak(&testing::PaganoPoint::tau_xy), peak(&testing::PaganoPoint::tau_xz),
          peak(&testing::PaganoPoint::tau_yz)};
}

enum class Refinement { kNone, kInPlane, kInPlaneAndShear };

// The recovery's peaks at Pagano's points, driven by the Navier solution of `section`'s RM plate.
Peaks recovered_peaks(const Laminate& laminate, const VamSection& section, double a,
                      Refinement refinement, bool exact_2d = false) {
  const NavierRmPlate plate =
      exact_2d ? NavierRmPlate(section, a, a, 1.0, exact_plate_amplitudes(laminate, a))
               : NavierRmPlate(section, a, a, 1.0);
  auto state_at = [&](double x, double y) {
    const testing::NavierRmPoint p = plate.at(x, y);
    PlateState s = p.state;
    if (refinement == Refinement::kNone) s.d2R.reset();
    if (refinement == Refinement::kInPlaneAndShear) s.d3R = p.d3R;
    return s;
  };
  auto peak = [&](double x, double y, int component) {
    const PlateState s = state_at(x, y);
    return peak_over_z(laminate, [&](int k, double z) {
      return recover_point(section, s, k, z).stress(component);
    });
  };
  return {peak(a / 2, a / 2, 0), peak(a / 2, a / 2, 2), peak(0, 0, 1), peak(0, a / 2, 3),
          peak(a / 2, 0, 4)};
}

// FSDT with k = 5/6 and no load coupling: the textbook 2-D model whose CLT ply stresses the issue
// quotes ("15 % below the exact sigma_x at S = 10 and 51 % at S = 4").
VamSection fsdt_section(const Laminate& laminate) {
  VamSection s = analyze_vam(laminate);
  s.G = fsdt_shear_stiffness(laminate, 5.0 / 6.0);
  s.Fbar_top.setZero();
  s.Fbar_bottom.setZero();
  return s;
}

void print_row(const char* name, double S, const Peaks& p, const Peaks& exact) {
  std::printf("| %g | %s | %+.1f %% | %+.1f %% | %+.1f %% | %+.1f %% | %+.1f %% |\n", S, name,
              100 * (p.sx / exact.sx - 1), 100 * (p.sy / exact.sy - 1),
              100 * (p.txy / exact.txy - 1), 100 * (p.txz / exact.txz - 1),
              100 * (p.tyz / exact.tyz - 1));
}

// The comparison table of docs/theory/failure.md: peak magnitudes through the thickness at
// Pagano's points, relative to the exact solution.
TEST(PaganoRecovery, ComparisonTable_NavierDriven) {
  const Laminate laminate = pagano_layup();
  const VamSection vam = analyze_vam(laminate);
  const VamSection fsdt = fsdt_section(laminate);
  std::printf("| S | 2-D model + recovery | sigma_x | sigma_y | tau_xy | tau_xz | tau_yz |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (double S : {4.0, 10.0, 100.0}) {
    const double a = S;  // h = 1
    const Peaks exact = exact_peaks(laminate, a);
    std::printf("| %g | exact (q S^2, q S) | %.4f | %.4f | %.4f | %.4f | %.4f |\n", S,
                exact.sx / (S * S), exact.sy / (S * S), exact.txy / (S * S), exact.txz / S,
                exact.tyz / S);
    print_row("FSDT k=5/6, CLT ply stress", S,
              recovered_peaks(laminate, fsdt, a, Refinement::kNone), exact);
    print_row("VAM, first-order recovery", S, recovered_peaks(laminate, vam, a, Refinement::kNone),
              exact);
    print_row("VAM, refined in-plane", S, recovered_peaks(laminate, vam, a, Refinement::kInPlane),
              exact);
    print_row("VAM, refined in-plane + shear", S,
              recovered_peaks(laminate, vam, a, Refinement::kInPlaneAndShear), exact);
    print_row("first-order, exact 2-D averages", S,
              recovered_peaks(laminate, vam, a, Refinement::kNone, true), exact);
    print_row("refined, exact 2-D averages", S,
              recovered_peaks(laminate, vam, a, Refinement::kInPlaneAndShear, true), exact);
    const NavierRmPlate rm(vam, a, a, 1.0);
    std::printf("  S = %g: centre deflection (thickness average) RM %.5f, exact %.5f (%+.1f %%)\n",
                S, rm.centre_deflection(), exact_plate_amplitudes(laminate, a)(2),
                100 * (rm.centre_deflection() / exact_plate_amplitudes(laminate, a)(2) - 1));
  }
}

// sigma_z at the centre of the plate, mid-plane and quarter points, exact against the recovery's
// two forms (vam.md 8): the simple one, linear from -t- to t+, and the integral of the 3-D
// equilibrium from the bottom face, which needs R_,ab. Values over the load q.
struct Sigma33 {
  double exact, linear, equilibrium;
};
Sigma33 sigma33_at(const Laminate& laminate, const VamSection& section, double a, double z) {
  const PaganoPlate exact(laminate, a, a, 1.0);
  const NavierRmPlate rm(section, a, a, 1.0);
  const RecoveredPoint p = recover_point(section, rm.at(a / 2, a / 2).state, laminate.ply_at(z), z);
  return {exact.at(z).sigma_zz, p.stress(5), *p.sigma33_equilibrium};
}

TEST(PaganoRecovery, Sigma33ProfileByEquilibrium) {
  const Laminate laminate = pagano_layup();
  const VamSection vam = analyze_vam(laminate);
  for (double S : {4.0, 10.0, 100.0})
    for (double z : {-0.25, 0.0, 0.25}) {
      const Sigma33 s = sigma33_at(laminate, vam, S, z);
      std::printf("S = %g, z = %+.2f h: sigma_z/q exact %.4f, linear form %.4f, equilibrium %.4f\n",
                  S, z, s.exact, s.linear, s.equilibrium);
      // The equilibrium form follows the exact profile to 1.1 % of q at S = 10 (4.1 % at S = 4,
      // where its first-order shear gradients miss the refinement); the linear form is off by
      // up to 9 % of q at every S.
      const double tolerance = S < 5 ? 0.045 : S < 50 ? 0.012 : 1e-3;
      EXPECT_NEAR(s.equilibrium, s.exact, tolerance) << "S " << S << " z " << z;
      if (z != 0.0) {
        EXPECT_GT(std::abs(s.linear - s.exact), 0.06) << "S " << S << " z " << z;
      }
    }
}

double worst(const Peaks& p, const Peaks& exact) {
  return std::max({std::abs(p.sx / exact.sx - 1), std::abs(p.sy / exact.sy - 1),
                   std::abs(p.txy / exact.txy - 1), std::abs(p.txz / exact.txz - 1),
                   std::abs(p.tyz / exact.tyz - 1)});
}

// The statement reproduced: today's (first-order) recovery puts the peak sigma_x 15 %
// below the exact value at S = 10 and 51 % below at S = 4.
TEST(PaganoRecovery, FirstOrderRecoveryUnderestimatesSigmaX_15PercentAtS10_51AtS4) {
  const Laminate laminate = pagano_layup();
  const VamSection vam = analyze_vam(laminate);
  for (const auto& [S, error] : {std::pair{10.0, -0.152}, std::pair{4.0, -0.505}}) {
    const Peaks p = recovered_peaks(laminate, vam, S, Refinement::kNone);
    EXPECT_NEAR(p.sx / exact_peaks(laminate, S).sx - 1, error, 0.005) << "S = " << S;
  }
}

// Acceptance (issue 16): within 3 % at S = 10 for the in-plane and transverse shear peaks, and
// 0.5 % at S = 100.
TEST(PaganoRecovery, RefinedRecoveryWithin3PercentAtS10) {
  const Laminate laminate = pagano_layup();
  const VamSection vam = analyze_vam(laminate);
  EXPECT_LT(worst(recovered_peaks(laminate, vam, 10, Refinement::kInPlaneAndShear),
                  exact_peaks(laminate, 10)),
            0.03);
  EXPECT_LT(worst(recovered_peaks(laminate, vam, 100, Refinement::kInPlaneAndShear),
                  exact_peaks(laminate, 100)),
            0.005);
}

// Acceptance at S = 4: within 10 % for sigma_x, sigma_y, tau_xz, tau_yz. tau_xy (+11.5 %) misses it
// because the 2-D Reissner-Mindlin solution itself is off at S = 4 (its centre deflection is 8 %
// above the exact thickness average): driven by the exact solution's thickness averages instead,
// the same recovery puts every in-plane peak within 7 % (tau_xy +6.4 %).
TEST(PaganoRecovery, RefinedRecoveryAtS4_Within10PercentBut_TauXy_LimitedByThe2dModel) {
  const Laminate laminate = pagano_layup();
  const VamSection vam = analyze_vam(laminate);
  const Peaks exact = exact_peaks(laminate, 4);
  const Peaks p = recovered_peaks(laminate, vam, 4, Refinement::kInPlaneAndShear);
  EXPECT_LT(std::abs(p.sx / exact.sx - 1), 0.10);
  EXPECT_LT(std::abs(p.sy / exact.sy - 1), 0.10);
  EXPECT_LT(std::abs(p.txz / exact.txz - 1), 0.10);
  EXPECT_LT(std::abs(p.tyz / exact.tyz - 1), 0.10);
  EXPECT_LT(std::abs(p.txy / exact.txy - 1), 0.12);
  const NavierRmPlate rm(vam, 4, 4, 1.0);
  EXPECT_GT(rm.centre_deflection() / exact_plate_amplitudes(laminate, 4)(2) - 1, 0.07);
  const Peaks q = recovered_peaks(laminate, vam, 4, Refinement::kInPlaneAndShear, true);
  EXPECT_LT(std::abs(q.sx / exact.sx - 1), 0.07);
  EXPECT_LT(std::abs(q.sy / exact.sy - 1), 0.07);
  EXPECT_LT(std::abs(q.txy / exact.txy - 1), 0.07);
}

}  // namespace
}  // namespace si
