// The F-bar face term on the nodal contact rows (indentation/face_thickening.hpp): against the
// interpolated traction's F-bar term with the nodal (lumped) rule, an independent code path
// (interpolated_contact.cpp) that reduces to nodal multipliers; the KINSOL solve against the
// linear fast path; the Jacobian against finite differences with a finite-thickness local law.
#include "indentation/face_thickening.hpp"

#include <gtest/gtest.h>

#include "contact/anisotropic_local_law.hpp"
#include "indentation/linear_indentation.hpp"
#include "indentation_test_support.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

using testing::coarse_cap_case;
using testing::IndentationFixture;

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

IndentationOptions nodal_fbar(const CaseFile& c) {
  IndentationOptions o;
  o.nodal_fbar = analyze_vam(c.laminate).Fbar_top;
  return o;
}

// With the lumped rule the interpolated traction's row of node i is the area-weighted sum of its
// elements' corner rows, the F-bar term included, and its multiplier t-bar_i w_i: the nodal rows
// with the face term must give the same shell state and forces to round-off.
TEST(FaceThickening, NodalFbarEqualsTheLumpedInterpolatedFbar) {
  const CaseFile c = coarse_cap_case("linear", "[45/-45]2S");
  IndentationFixture nodal(c, nodal_fbar(c));
  IndentationOptions o;
  o.interpolated_traction = true;
  o.interpolated.gauss_points = 0;
  o.interpolated.fbar = true;
  o.interpolated.fbar_top = analyze_vam(c.laminate).Fbar_top;
  IndentationFixture lumped(c, o);
  IndentationFixture plain(c);
  ASSERT_EQ(nodal.problem->candidates(), lumped.problem->candidates());
  LinearIndentation a(*nodal.problem), b(*lumped.problem), without(*plain.problem);
  const int nf = nodal.problem->num_shell_unknowns();
  for (double h : {0.5, 1.0, 2.0}) {
    const cont::Vector za = a.solve(h), zb = b.solve(h), z0 = without.solve(h);
    EXPECT_LT(relative_difference(zb.head(nf), za.head(nf)), 1e-10) << h;
    const double fa = nodal.problem->evaluate(za, h).force;
    const double fb = lumped.problem->evaluate(zb, h).force;
    EXPECT_NEAR(fa, fb, 1e-10 * fb) << h;
    // The term is there: it moves the shell by more than the comparison's tolerance.
    EXPECT_GT(relative_difference(za.head(nf), z0.head(nf)), 1e-4) << h;
  }
}

// The KINSOL route (residual, shell force and Jacobian of the nodal rows) against the linear fast
// path (the gap matrix): the same solution to 1e-10.
TEST(FaceThickening, KinsolAndLinearFastPathAgree) {
  const CaseFile c = coarse_cap_case("linear", "[0/90]2S");
  IndentationFixture f(c, nodal_fbar(c));
  IndentationProblem& p = *f.problem;
  LinearIndentation fast(p);
  cont::Vector z = p.initial_point();
  const int nf = p.num_shell_unknowns();
  for (double h : {0.3, 1.0, 2.0}) {
    const cont::NewtonResult r = cont::solve_at(p, z, h, testing::tight_kinsol_settings(p));
    ASSERT_TRUE(r.converged) << r.reason;
    const cont::Vector zf = fast.solve(h);
    EXPECT_LT(relative_difference(zf.head(nf), z.head(nf)), 1e-10) << h;
    EXPECT_LT(relative_difference(zf.tail(z.size() - nf), z.tail(z.size() - nf)), 1e-10) << h;
  }
}

// With the finite-thickness plate law (its alpha borders the system) and the face term.
TEST(FaceThickening, PlateLaw_JacobianMatchesFiniteDifferences) {
  const CaseFile c = coarse_cap_case("linear", "[0/90]2S");
  IndentationOptions o = nodal_fbar(c);
  o.local =
      anisotropic_local_law(c.laminate, {LocalSupport::kPlate, LocalPlies::kResolved, 10.98, 0.0});
  IndentationFixture f(c, testing::exact_solves(o));
  testing::expect_jacobian_matches_fd(*f.problem, 0.3, 0.5);
}

}  // namespace
}  // namespace si
