// The stiffness extrema at the curve's scale (analysis/stiffness_wells.hpp), against closed
// forms, and what they must not report:
//  * an exact parabola s = 10 + 2 (h - 3)^2: the vertex at 3 and the stiffness 10 to roundoff;
//  * the same parabola with the sawtooth of contact kinks (the stiffness falls linearly within
//    each contact set and jumps up where a node enters): the vertex within 0.05 mm of 3 and
//    within its stated accuracy;
//  * a maximum is the minimum of -s;
//  * two minima apart by a bump of more than 5 % are two wells, by less they are one;
//  * none on a rising stiffness with kinks of 3 % and of 10 %, none where the path ends inside
//    the well (the stiffness has not risen again), none on a constant stiffness.
#include "analysis/stiffness_wells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <tuple>

namespace si {
namespace {

std::vector<StiffnessSample> sampled(const std::function<double(double)>& s, double step,
                                     double end) {
  std::vector<StiffnessSample> out;
  for (int i = 0; i * step <= end + 1e-12; ++i) out.push_back({i * step, s(i * step)});
  return out;
}

double parabola(double h) {
  return 10 + 2 * (h - 3) * (h - 3);
}

// A sawtooth of mean zero and period `period`: + jump / 2 just after each kink, falling
// linearly to - jump / 2 just before the next.
double sawtooth(double h, double period, double jump) {
  const double phase = std::fmod(h, period) / period;
  return jump * (0.5 - phase);
}

TEST(StiffnessWells, ExactParabolaVertexToRoundoff) {
  const auto samples = sampled(parabola, 0.05, 6.0);
  const auto wells = stiffness_wells(samples, 0.05);
  ASSERT_EQ(wells.size(), 1u);
  EXPECT_EQ(wells[0].kind, CriticalKind::kStiffnessMin);
  // The well: 2 (h - 3)^2 <= 0.5, |h - 3| <= 0.5, bounded by the samples just outside.
  EXPECT_NEAR(wells[0].from, 2.45, 1e-9);
  EXPECT_NEAR(wells[0].to, 3.55, 1e-9);
  const auto v = fitted_vertex(samples, wells[0]);
  ASSERT_TRUE(v.has_value());
  EXPECT_NEAR(v->depth, 3.0, 1e-10);
  EXPECT_NEAR(v->stiffness, 10.0, 1e-10);
  EXPECT_LE(std::abs(v->depth - 3.0), v->accuracy + 1e-12);
}

TEST(StiffnessWells, ParabolaWithContactKinksVertexWithinItsAccuracy) {
  // Kinks every 0.13 mm, jumps of 2 % of the minimum stiffness, samples every 0.02 mm.
  for (double offset : {0.0, 0.041, 0.087}) {
    const auto samples =
        sampled([&](double h) { return parabola(h) + sawtooth(h + offset, 0.13, 0.2); }, 0.02, 6.0);
    const auto wells = stiffness_wells(samples, 0.05);
    ASSERT_EQ(wells.size(), 1u) << offset;
    const auto v = fitted_vertex(samples, wells[0]);
    ASSERT_TRUE(v.has_value()) << offset;
    EXPECT_NEAR(v->depth, 3.0, 0.05) << offset;
    EXPECT_LE(std::abs(v->depth - 3.0), v->accuracy) << offset;
    EXPECT_GT(v->accuracy, 1e-4) << offset;  // the scatter is stated, not hidden
    EXPECT_NEAR(v->stiffness, 10.0, 0.1) << offset;
  }
}

TEST(StiffnessWells, MaximumIsTheMinimumOfTheNegative) {
  const auto samples = sampled([](double h) { return 30 - parabola(h); }, 0.05, 6.0);
  const auto wells = stiffness_wells(samples, 0.05);
  ASSERT_EQ(wells.size(), 1u);
  EXPECT_EQ(wells[0].kind, CriticalKind::kStiffnessMax);
  const auto v = fitted_vertex(samples, wells[0]);
  ASSERT_TRUE(v.has_value());
  EXPECT_NEAR(v->depth, 3.0, 1e-10);
  EXPECT_NEAR(v->stiffness, 20.0, 1e-10);
}

// s = 10 + (b / 2) (1 - cos(2 pi (h - 3) / 3)) + 3 d^2, d the distance outside [3, 6]: minima
// of 10 at h = 3 and 6 with a bump of b between them. For b = 8 % of 10 they are two wells; for
// 3 % one (and the bump is no maximum: it does not stand 5 % above its surroundings).
double two_minima(double h, double bump) {
  const double outside = h < 3 ? 3 - h : (h > 6 ? h - 6 : 0.0);
  return 10 + 0.5 * bump * (1 - std::cos(2 * M_PI * (h - 3) / 3)) + 3 * outside * outside;
}

TEST(StiffnessWells, TwoMinimaApartByMoreThanTheFractionAreTwoWells) {
  for (const auto& [bump, minima, maxima] : {std::tuple{0.8, 2, 1}, std::tuple{0.3, 1, 0}}) {
    const auto samples = sampled([&](double h) { return two_minima(h, bump); }, 0.05, 8.0);
    int found_minima = 0, found_maxima = 0;
    for (const auto& w : stiffness_wells(samples, 0.05)) {
      found_minima += w.kind == CriticalKind::kStiffnessMin;
      found_maxima += w.kind == CriticalKind::kStiffnessMax;
    }
    EXPECT_EQ(found_minima, minima) << bump;
    EXPECT_EQ(found_maxima, maxima) << bump;
  }
}

TEST(StiffnessWells, NoneOnARisingStiffnessWithKinks) {
  for (double jump : {0.03, 0.10}) {
    const auto samples =
        sampled([&](double h) { return (10 + 2 * h) * (1 + sawtooth(h, 0.13, jump)); }, 0.02, 6.0);
    for (const auto& w : stiffness_wells(samples, 0.05))
      EXPECT_FALSE(fitted_vertex(samples, w).has_value()) << jump << " " << w.from;
  }
}

TEST(StiffnessWells, NoneWhereThePathEndsInsideTheWell) {
  // The parabola cut at its vertex plus 0.2 mm: the stiffness has not risen 5 % again.
  EXPECT_TRUE(stiffness_wells(sampled(parabola, 0.05, 3.2), 0.05).empty());
}

TEST(StiffnessWells, NoneOnAConstantStiffness) {
  EXPECT_TRUE(stiffness_wells(sampled([](double) { return 9e3; }, 0.1, 5.0), 0.05).empty());
}

}  // namespace
}  // namespace si
