// In-plane bending of a cantilever strip: the membrane counterpart of the locking test. Strip in
// the x-y plane, length L = 10 along x, depth h = 1 along y (in-plane), thickness t = 0.1, E = 1e7,
// nu = 0.3, root x = 0 clamped, total tip shear P = 1 along +y spread uniformly over the tip edge
// (line load). Reference: Timoshenko beam theory, tip deflection
//   delta = P L^3 / (3 E I) + P L / (k G A),  I = t h^3 / 12, A = t h, G = E / (2 (1 + nu)),
//   k = 5/6  (shear term 0.8 % of the total here; S. Timoshenko, J.M. Gere, "Mechanics of
//   Materials", 1972, sec. 9.12; MacNeal & Harder 1985 use the same formula for their straight
//   cantilever, reference 0.1081 for L/h = 30).
// EAS-4 represents pure in-plane bending of rectangles exactly (Simo & Rifai 1990), so mitc4 must
// be within 2 % with ONE element across the depth; the bilinear membrane (mitc4-plain) locks in
// parasitic shear and is the control that shows the test can fail.
#include <gtest/gtest.h>

#include <string>

#include "../verification_record.hpp"
#include "model/plate_meshes.hpp"
#include "shell_benchmark_support.hpp"

namespace si::verification {
namespace {

constexpr double kLength = 10, kDepth = 1, kThickness = 0.1, kModulus = 1e7, kPoisson = 0.3;

double timoshenko_tip_deflection(double P) {
  const double I = kThickness * kDepth * kDepth * kDepth / 12, A = kThickness * kDepth;
  const double G = kModulus / (2 * (1 + kPoisson));
  return P * kLength * kLength * kLength / (3 * kModulus * I) + P * kLength / (5.0 / 6.0 * G * A);
}

// Mean in-plane deflection of the tip nodes of an n_length x n_depth mesh.
ConvergenceRow inplane_cantilever(ElementType element, int n_length, int n_depth) {
  const double P = 1;
  BenchmarkModel m;
  m.mesh = rectangular_plate_mesh(kLength, kDepth, n_length, n_depth);
  m.supports = {{SupportKind::kClamped, "edge_x0", -1, {}}};
  m.law = isotropic_shell_law(kModulus, kPoisson, kThickness);
  const std::vector<int>& tip = m.mesh.node_sets.at("edge_x1");  // ordered along the edge
  m.loads.lines = {{tip, Vector3d(0, P / kDepth, 0)}};
  const BenchmarkSolution s = solve_linear(m, element);
  expect_equilibrium(s);
  double mean = 0;
  for (int node : tip) mean += s.state[node].u.y() / tip.size();
  return {make_shell_element(element)->name() + " " + std::to_string(n_length) + "x" +
              std::to_string(n_depth),
          mean, s.seconds};
}

TEST(InPlaneCantilever, TipShear_Mitc4_10x1_and_10x2_TimoshenkoBeam_PL3over3EI_plus_PLoverkGA) {
  const double reference = timoshenko_tip_deflection(1);
  for (int n_depth : {1, 2}) {
    const ConvergenceRow eas = inplane_cantilever(ElementType::kMitc4, 10, n_depth);
    const ConvergenceRow plain = inplane_cantilever(ElementType::kMitc4Plain, 10, n_depth);
    for (const ConvergenceRow& r : {eas, plain})
      std::printf("in-plane cantilever %s: tip %.6g, Timoshenko %.6g, ratio %.4f\n", r.mesh.c_str(),
                  r.value, reference, r.value / reference);
    EXPECT_NEAR(eas.value / reference, 1.0, 0.02) << eas.mesh;
    test::record_verification("linear-benchmarks", "In-plane cantilever, tip shear, " + eas.mesh,
                              reference, eas.value, 0.02,
                              "Timoshenko beam P L^3/(3EI) + P L/(kGA)");
    EXPECT_LT(plain.value / reference, 0.98) << plain.mesh;  // control: the bilinear membrane locks
  }
}

}  // namespace
}  // namespace si::verification
