// Depth and force at a given indenter work (quasi-static equivalence of an impact, Nettles &
// Douglas NASA/TP-2000-210481) on closed-form force-depth paths:
//   F = k h      : trapezoidal work is exact, so is the located depth;
//   F = c h^3    : cubic Hermite with exact slopes is exact;
//   F = k h^1.5  : W = 0.4 k h^2.5 (a Hertz-like contact law), second-order convergence for the
//                  trapezoid, higher for Hermite;
// and the outcomes that must not be extrapolated or misplaced.
#include "damage/impact_energy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

namespace si {
namespace {

ForceDepthPath sampled(double h_max, int segments, double (*F)(double), double (*dF)(double)) {
  ForceDepthPath p;
  for (int i = 0; i <= segments; ++i) {
    const double h = h_max * i / segments;
    p.depth.push_back(h);
    p.force.push_back(F(h));
    p.slope.push_back(dF(h));
  }
  return p;
}

constexpr double kK = 2000;  // N/mm^1.5
double power15(double h) {
  return kK * std::pow(h, 1.5);
}
double power15_slope(double h) {
  return 1.5 * kK * std::sqrt(h);
}
double power15_depth_at(double W) {
  return std::pow(W / (0.4 * kK), 0.4);
}  // W = 0.4 k h^2.5
double linear(double h) {
  return 300 * h;
}
double linear_slope(double) {
  return 300;
}
double cubic(double h) {
  return 50 * h * h * h;
}
double cubic_slope(double h) {
  return 150 * h * h;
}

TEST(ImpactEnergy, TrapezoidIsExactForALinearPath) {
  const ForceDepthPath p = sampled(2.0, 7, linear, linear_slope);
  for (double E : {0.0, 1.0, 37.5, 599.9, 600.0}) {  // W = 150 h^2, W(2) = 600
    const EnergyPoint e = depth_at_energy(p, E, WorkInterpolation::kTrapezoid);
    ASSERT_EQ(e.outcome, EnergyOutcome::kReached) << E;
    EXPECT_NEAR(e.depth, std::sqrt(E / 150), 1e-13) << E;
    EXPECT_NEAR(e.force, 300 * std::sqrt(E / 150), 1e-10) << E;
  }
}

TEST(ImpactEnergy, HermiteIsExactForACubicPath) {
  const ForceDepthPath p = sampled(3.0, 5, cubic, cubic_slope);
  for (double E : {0.5, 100.0, 1000.0}) {  // W = 12.5 h^4, W(3) = 1012.5
    const EnergyPoint e = depth_at_energy(p, E, WorkInterpolation::kHermite);
    ASSERT_EQ(e.outcome, EnergyOutcome::kReached) << E;
    EXPECT_NEAR(e.depth, std::pow(E / 12.5, 0.25), 1e-12) << E;
    EXPECT_NEAR(e.force, cubic(e.depth), 1e-9) << E;
  }
  EXPECT_NEAR(path_work(p, WorkInterpolation::kHermite).back(), 1012.5, 1e-10);
}

// F = k h^1.5 from 0 to 2 mm: the located depth converges to (E/(0.4 k))^0.4, the trapezoid at
// second order (error ratio ~4 per halving), Hermite at order 2.5 (ratio 2^2.5 = 5.66): its error
// comes from the first segment, where F'' = 0.75 k h^-0.5 is unbounded; the work at the reported
// point is E (the interpolation of the force is the one the work integrates).
TEST(ImpactEnergy, PowerLawPathConvergesToTheClosedForm) {
  const double E = 1500;  // N mm; W(2) = 0.4 k 2^2.5 = 4525 N mm
  const double exact = power15_depth_at(E);
  double previous_trapezoid = 0, previous_hermite = 0;
  for (int n : {10, 20, 40, 80}) {
    const ForceDepthPath p = sampled(2.0, n, power15, power15_slope);
    const EnergyPoint t = depth_at_energy(p, E, WorkInterpolation::kTrapezoid);
    const EnergyPoint h = depth_at_energy(p, E, WorkInterpolation::kHermite);
    const double et = std::abs(t.depth - exact), eh = std::abs(h.depth - exact);
    std::printf("n %3d: trapezoid error %.3e mm, Hermite %.3e mm\n", n, et, eh);
    EXPECT_LT(eh, et);
    if (previous_trapezoid > 0) {
      EXPECT_NEAR(previous_trapezoid / et, 4.0, 0.4) << n;
      EXPECT_NEAR(previous_hermite / eh, std::pow(2.0, 2.5), 0.3) << n;
    }
    previous_trapezoid = et;
    previous_hermite = eh;
    // The point's work is E on the interpolation that located it.
    ForceDepthPath upto = p;
    upto.depth.resize(t.segment + 1);
    upto.force.resize(t.segment + 1);
    upto.depth.push_back(t.depth);
    upto.force.push_back(t.force);
    EXPECT_NEAR(path_work(upto, WorkInterpolation::kTrapezoid).back(), E, 1e-9 * E);
  }
  EXPECT_LT(std::abs(depth_at_energy(sampled(2.0, 80, power15, power15_slope), E,
                                     WorkInterpolation::kTrapezoid)
                         .depth -
                     exact),
            1e-4);
}

// The trapezoidal work is path.csv's work column: W_i+1 = W_i + (F_i + F_i+1)(h_i+1 - h_i)/2.
TEST(ImpactEnergy, TrapezoidWorkIsThePathColumn) {
  const ForceDepthPath p = sampled(1.0, 4, power15, power15_slope);
  const std::vector<double> W = path_work(p, WorkInterpolation::kTrapezoid);
  double sum = 0;
  for (size_t i = 1; i < W.size(); ++i) {
    sum += 0.5 * (p.force[i] + p.force[i - 1]) * (p.depth[i] - p.depth[i - 1]);
    EXPECT_NEAR(W[i], sum, 1e-12 * sum);
  }
}

// An energy above the path's work is reported as beyond the path with no depth or force; energies
// come back in the order asked; a negative energy is refused.
TEST(ImpactEnergy, BeyondThePathIsAnOutcomeNotAnExtrapolation) {
  const ForceDepthPath p = sampled(2.0, 20, power15, power15_slope);
  const double total = path_work(p, WorkInterpolation::kTrapezoid).back();
  const std::vector<EnergyPoint> e =
      depths_at_energies(p, {0.5 * total, 1.01 * total}, WorkInterpolation::kTrapezoid);
  EXPECT_EQ(e[0].outcome, EnergyOutcome::kReached);
  EXPECT_EQ(e[1].outcome, EnergyOutcome::kBeyondPath);
  EXPECT_TRUE(std::isnan(e[1].depth));
  EXPECT_TRUE(std::isnan(e[1].force));
  EXPECT_EQ(e[1].segment, -1);
  EXPECT_DOUBLE_EQ(e[1].max_work, total);
  EXPECT_EQ(depth_at_energy(p, 0.0, WorkInterpolation::kTrapezoid).depth, 0.0);
  try {
    depth_at_energy(p, -1.0, WorkInterpolation::kTrapezoid);
    FAIL() << "accepted a negative energy";
  } catch (const Error& err) {
    EXPECT_EQ(err.kind(), ErrorKind::kInput);
    EXPECT_EQ(err.where().key, "impact_energy");
  }
  ForceDepthPath no_slopes = p;
  no_slopes.slope.clear();
  EXPECT_THROW(path_work(no_slopes, WorkInterpolation::kHermite), Error);
}

// A snap-back: the depth turns back while the force drops, so the work falls along that stretch;
// the first point along the path where the work equals E is reported, not a later one.
TEST(ImpactEnergy, SnapBackPathReportsTheFirstCrossing) {
  ForceDepthPath p;
  p.depth = {0, 1, 2, 1.8, 3};
  p.force = {0, 100, 200, 50, 150};
  // Work: 0, 50, 200, 175, 295.
  const EnergyPoint e = depth_at_energy(p, 180, WorkInterpolation::kTrapezoid);
  ASSERT_EQ(e.outcome, EnergyOutcome::kReached);
  EXPECT_EQ(e.segment, 1);  // reached on the way to 2 mm, before the snap-back
  // 50 + 100 s + 50 s^2 = 180 on [1, 2]: s = (-100 + sqrt(10000 + 26000)) / 100.
  const double s = (-100 + std::sqrt(36000.0)) / 100;
  EXPECT_NEAR(e.depth, 1 + s, 1e-12);
  EXPECT_NEAR(e.force, 100 + 100 * s, 1e-9);
}

}  // namespace
}  // namespace si
