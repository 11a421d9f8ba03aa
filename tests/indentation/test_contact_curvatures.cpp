// Curvature extremes over the contact zone (paper-notes item 7), against the whole-mesh nodal
// recovery (model/nodal_resultants.hpp, nodal_strains: a different route through every
// element) restricted to the nodes in contact.
#include <gtest/gtest.h>

#include "continuation/kinsol_corrector.hpp"
#include "indentation_test_support.hpp"
#include "model/nodal_resultants.hpp"

namespace si {
namespace {

using testing::coarse_cap_case;
using testing::IndentationFixture;

TEST(ContactCurvatures, ExtremesOverTheContactNodesMatchTheWholeMeshRecovery) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[45/-45]2S"));
  IndentationProblem& p = *f.problem;
  cont::Vector z = p.initial_point();
  const double h = 2.0;
  ASSERT_TRUE(cont::solve_at(p, z, h, testing::tight_kinsol_settings(p)).converged);
  const IndentationState s = p.evaluate(z, h);
  ASSERT_GE(s.contact_nodes, 3);  // a zone, not a point

  const Eigen::MatrixXd strains =
      nodal_strains(f.model.mesh, p.assembler(), *f.model.element, p.node_states(z));
  const double lambda_max = *std::max_element(s.multipliers.begin(), s.multipliers.end());
  Vector3d lo = Vector3d::Constant(1e300), hi = Vector3d::Constant(-1e300);
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    if (!(s.multipliers[i] > 1e-9 * lambda_max)) continue;
    const Vector3d k = strains.row(s.nodes[i]).segment<3>(3).transpose();
    lo = lo.cwiseMin(k);
    hi = hi.cwiseMax(k);
  }
  const double scale = hi.cwiseAbs().maxCoeff();
  EXPECT_LT((s.contact_curvature_min - lo).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((s.contact_curvature_max - hi).cwiseAbs().maxCoeff(), 1e-12 * scale);
  // The apex is in contact: its curvature lies between the extremes.
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(s.contact_curvature_min[c], s.apex_curvature[c] + 1e-12 * scale) << c;
    EXPECT_GE(s.contact_curvature_max[c], s.apex_curvature[c] - 1e-12 * scale) << c;
  }
  // The contact zone is curved along the indenter, unlike the apex alone: the extremes differ.
  EXPECT_GT(s.contact_curvature_max[0] - s.contact_curvature_min[0], 1e-6 * scale);
}

}  // namespace
}  // namespace si
