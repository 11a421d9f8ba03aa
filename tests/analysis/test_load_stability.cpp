// The load problem's stability (analysis/load_stability.cpp): the chart Hessian it analyses, its
// symmetry at equilibrium under a conservative follower pressure, and the counts and lowest
// eigenvalues through continuation/'s tools against a dense eigen-solve of the same matrix.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "analysis/load_problem.hpp"
#include "model/spherical_cap_mesh.hpp"
#include "model/supports.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {
namespace {

// A coarse whole clamped cap (R = 100 mm, h = 1 mm, base radius 40 mm) under a follower external
// pressure of 20 MPa at load factor 1 (about 0.8 of the classical pressure of the sphere).
struct PressedCap {
  Mesh mesh = [] {
    SphericalCapMeshSpec spec;
    spec.base_radius = 40;
    spec.sphere_radius = 100;
    spec.size_apex = spec.size_edge = 8;
    spec.refine_radius = 20;
    return spherical_cap_mesh(spec);
  }();
  std::unique_ptr<ShellElement> element = make_shell_element(ElementType::kMitc4);
  ShellLaw law = isotropic_shell_law(2e5, 1.0 / 3.0, 1.0);
  Loads loads = [] {
    Loads l;
    l.pressures.push_back({-20.0, true, {}});
    return l;
  }();
  LoadProblem problem{
      mesh, {{SupportKind::kClamped, "edge", -1, {}}}, *element, law, loads, LoadProblemOptions{}};

  // Newton from the undeformed state to equilibrium at load factor `lambda`.
  cont::Vector equilibrium(double lambda) {
    cont::Vector x = problem.initial_point(), F;
    for (int it = 0; it < 30; ++it) {
      EXPECT_TRUE(problem.residual(x, lambda, F));
      if (F.cwiseAbs().maxCoeff() < 1e-10 * problem.force_scale()) break;
      EXPECT_TRUE(problem.factorize(x, lambda));
      EXPECT_TRUE(problem.solve(F));
      x -= F;
    }
    EXPECT_TRUE(problem.residual(x, lambda, F));
    EXPECT_LT(F.cwiseAbs().maxCoeff(), 1e-9 * problem.force_scale());
    return x;
  }
};

// At equilibrium T'J is the Hessian of the potential: symmetric, the pressure on a surface with
// a clamped boundary being conservative (Schweizerhof & Ramm 1984). Off equilibrium it is not
// (the drilling term of the unbalanced moments, and (dT'/dx) F), which the measure must show.
TEST(LoadStability, ChartHessianIsSymmetricAtEquilibriumOnly) {
  PressedCap cap;
  const cont::Vector x = cap.equilibrium(0.5);
  const double at_equilibrium = cap.problem.stability_matrix(x, 0.5).asymmetry;
  cont::Vector off = x;
  for (int i = 0; i < off.size(); ++i) off[i] += 1e-3 * std::sin(1.0 + i);
  const double off_equilibrium = cap.problem.stability_matrix(off, 0.5).asymmetry;
  std::printf("skew part of T'J: %.2e at equilibrium, %.2e off it\n", at_equilibrium,
              off_equilibrium);
  EXPECT_LT(at_equilibrium, 1e-9);
  EXPECT_GT(off_equilibrium, 1e3 * at_equilibrium);
}

// The count and the lowest eigenvalues that stability() reports (CHOLMOD first, Lanczos) are
// those of a dense eigen-solve of the matrix it analyses; before the first critical point the
// cap is stable.
TEST(LoadStability, LowestEigenvaluesMatchDenseEigenSolve) {
  PressedCap cap;
  const cont::Vector x = cap.equilibrium(0.5);
  ASSERT_TRUE(cap.problem.factorize(x, 0.5));  // stability() then reuses this Jacobian
  cont::Stability s;
  ASSERT_TRUE(cap.problem.stability(x, 0.5, 3, s));
  const Eigen::MatrixXd H(cap.problem.stability_matrix(x, 0.5).H);
  const Eigen::VectorXd dense = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues();
  int negative = 0;
  for (int i = 0; i < dense.size(); ++i) negative += dense[i] < 0;
  EXPECT_EQ(s.negative, negative);
  EXPECT_EQ(s.negative, 0);
  ASSERT_EQ(s.eigenvalues.size(), 3);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(s.eigenvalues[k], dense[k], 1e-8 * std::abs(dense[k])) << "eigenvalue " << k;
  ASSERT_EQ(s.modes.size(), 3u);
  EXPECT_EQ(s.modes[0].size(), cap.problem.size());
}

}  // namespace
}  // namespace si
