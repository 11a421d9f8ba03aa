// Checks of the normal-line finite-element model (shared/docs/vam.md 4) that do not need the
// full section analysis: mesh layout, quadrature, shape functions and assembled matrices.
#include "section/normal_line_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "laminate_fixtures.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

using testing::paper_material;
using testing::stack;

// An n-point Gauss-Legendre rule integrates x^k exactly for k <= 2n - 1:
// int_{-1}^{1} x^k = 2/(k+1) for even k, 0 for odd k.
TEST(NormalLineMesh, GaussLegendreExactToDegree2nMinus1) {
  for (int n = 1; n <= 8; ++n) {
    const GaussRule rule = gauss_legendre(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0;
      for (int g = 0; g < n; ++g) sum += rule.weights[g] * std::pow(rule.points[g], k);
      EXPECT_NEAR(sum, k % 2 == 0 ? 2.0 / (k + 1) : 0.0, 1e-14) << "n " << n << " k " << k;
    }
  }
}

// vam.md 4.1: p * n_el * N + 1 nodes, 3 DOFs each, shared nodes on the ply interfaces.
TEST(NormalLineMesh, NodesAndDofsFollowOrderAndElements) {
  const Laminate laminate = stack(paper_material(), {0, 90, 45}, 0.5);
  const NormalLineMesh mesh(laminate, 3, 2);
  EXPECT_EQ(mesh.nodes().size(), 3u * 2u * 3u + 1u);
  EXPECT_EQ(mesh.dofs(), 3 * 19);
  EXPECT_EQ(mesh.elements().size(), 6u);
  const std::vector<double> z = laminate.interfaces();
  for (int k = 0; k <= 3; ++k) EXPECT_DOUBLE_EQ(mesh.nodes()[6 * k], z[k]);
  EXPECT_THROW(NormalLineMesh(laminate, 0, 1), Error);
  EXPECT_THROW(NormalLineMesh(laminate, 2, 0), Error);
}

// Lagrange shape functions: Kronecker property at the element nodes, partition of unity and
// derivatives summing to zero elsewhere.
TEST(NormalLineMesh, ShapeFunctionsInterpolateAndSumToOne) {
  const NormalLineMesh mesh(stack(paper_material(), {0}, 1.0), 4, 1);
  for (int j = 0; j <= 4; ++j) {
    const NormalLinePoint p = mesh.point(mesh.nodes()[j], 0);
    for (int i = 0; i <= 4; ++i) EXPECT_NEAR(p.N(i), i == j ? 1.0 : 0.0, 1e-14);
  }
  const NormalLinePoint p = mesh.point(0.123, 0);
  EXPECT_NEAR(p.N.sum(), 1.0, 1e-14);
  EXPECT_NEAR(p.dN.sum(), 0.0, 1e-12);
  // x3 is reproduced exactly: sum N_j x_j = x3 and sum dN_j x_j = 1.
  const Eigen::Map<const Eigen::VectorXd> x(mesh.nodes().data(), 5);
  EXPECT_NEAR(p.N.dot(x), 0.123, 1e-14);
  EXPECT_NEAR(p.dN.dot(x), 1.0, 1e-12);
}

// vam.md 4.2: E annihilates the rigid translations, psi^T H psi = I, and for one ply
// D_ee = [[Cp h, 0], [0, Cp h^3/12]] with Cp the in-plane block of C (int x3 = 0 about the mid).
TEST(NormalLineMesh, AssembledMatricesHaveTheirDefiningProperties) {
  const double h = 1.9;
  const Laminate laminate = stack(paper_material(), {30}, h);
  const NormalLineMesh mesh(laminate, 4, 2);
  const NormalLineMatrices m = assemble_normal_line(mesh);
  const Eigen::MatrixXd K = mesh.kernel();
  EXPECT_LT((m.E * K).norm(), 1e-12 * m.E.norm());
  EXPECT_LT((K.transpose() * m.H_psi / std::sqrt(h) - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  const Matrix3d Cp = laminate.plies[0].stiffness_yu().topLeftCorner<3, 3>();
  EXPECT_LT((m.D_ee.topLeftCorner<3, 3>() - Cp * h).norm(), 1e-12 * Cp.norm() * h);
  EXPECT_LT((m.D_ee.bottomRightCorner<3, 3>() - Cp * h * h * h / 12).norm(),
            1e-12 * Cp.norm() * h * h * h);
  const double coupling = m.D_ee.topRightCorner<3, 3>().norm();
  EXPECT_LT(coupling, 1e-12 * Cp.norm() * h * h);
  EXPECT_LT((m.D_ll[0][1] - m.D_ll[1][0].transpose()).norm(), 1e-12 * m.D_ll[0][1].norm());
}

}  // namespace
}  // namespace si
