#include "section/reissner_mindlin_fit.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace si {
namespace {

constexpr int kBaseUnknowns = 27;        // X11, X12, X22, c1 (row-major 2x6), c2 (row-major 2x6)
constexpr int kCompatUnknowns = 24;      // K (row-major 2x12)
constexpr double kSvdThreshold = 1e-12;  // relative to the largest singular value (vam.md 13)

// D_a of vam.md 6.2: eps = R - D1 gamma_,1 - D2 gamma_,2.
Eigen::Matrix<double, 6, 2> shear_gradient_map(int alpha) {
  Eigen::Matrix<double, 6, 2> D = Eigen::Matrix<double, 6, 2>::Zero();
  if (alpha == 0) {
    D(3, 0) = 1.0;  // k11 <- (2g13),1
    D(4, 1) = 1.0;  // k12+k21 <- (2g23),1
  } else {
    D(4, 0) = 1.0;  // k12+k21 <- (2g13),2
    D(5, 1) = 1.0;  // k22 <- (2g23),2
  }
  return D;
}

// P of vam.md 6.4.1: P R' = [k11,2 - k12,1 ; k22,1 - k12,2] (zero for compatible curvatures).
Eigen::Matrix<double, 2, 12> compatibility_operator() {
  Eigen::Matrix<double, 2, 12> P = Eigen::Matrix<double, 2, 12>::Zero();
  P(0, 6 + 3) = 1.0;
  P(0, 4) = -0.5;
  P(1, 5) = 1.0;
  P(1, 6 + 4) = -0.5;
  return P;
}

struct FitProblem {
  Matrix6d A;
  std::array<ShearRelaxation, 2> S;
  double thickness;
  bool compat;

  int unknowns() const { return kBaseUnknowns + (compat ? kCompatUnknowns : 0); }

  Matrix2d X_of(const Eigen::VectorXd& x) const {
    Matrix2d X;
    X << x(0), x(1), x(1), x(2);
    return X;
  }

  // The part of the residual operator M(x) = H + coupling(x) that is linear in x (12 x 12,
  // symmetric). Kept apart from H so that the Jacobian is built without cancellation: H is
  // O(C h^3) while the c-terms are O(C h), and r(e_k) - r(0) would lose those digits.
  Eigen::MatrixXd coupling(const Eigen::VectorXd& x) const {
    const Matrix2d X = X_of(x);
    std::array<ShearRelaxation, 2> c;
    for (int a = 0; a < 2; ++a)
      for (int r = 0; r < 2; ++r)
        for (int m = 0; m < 6; ++m) c[a](r, m) = x(3 + 12 * a + 6 * r + m);
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(12, 12);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        M.block<6, 6>(6 * a, 6 * b) +=
            A * shear_gradient_map(a) * X * shear_gradient_map(b).transpose() * A +
            c[a].transpose() * S[b] + S[a].transpose() * c[b];
      }
    if (compat) {
      Eigen::Matrix<double, 2, 12> K;
      for (int r = 0; r < 2; ++r)
        for (int m = 0; m < 12; ++m) K(r, m) = x(kBaseUnknowns + 12 * r + m);
      const Eigen::Matrix<double, 2, 12> P = compatibility_operator();
      M += P.transpose() * K + K.transpose() * P;
    }
    return M;
  }

  // The 78 weighted equations of a 12 x 12 operator: upper triangle scaled by T_i T_j (6.3).
  Eigen::VectorXd equations(const Eigen::MatrixXd& M) const {
    const double t_kappa = std::sqrt(12.0) / thickness;
    auto weight = [t_kappa](int i) { return (i % 6) < 3 ? 1.0 : t_kappa; };
    Eigen::VectorXd r(78);
    int k = 0;
    for (int i = 0; i < 12; ++i)
      for (int j = i; j < 12; ++j) r(k++) = M(i, j) * weight(i) * weight(j);
    return r;
  }
};

// Minimum-norm least-squares solution of min |r0 + J x| by SVD after column equilibration,
// dropping singular values below kSvdThreshold * sigma_max (J is rank deficient, vam.md 6.3).
Eigen::VectorXd solve_least_squares(const Eigen::MatrixXd& J, const Eigen::VectorXd& r0,
                                    int& rank) {
  Eigen::VectorXd scale = J.colwise().norm().transpose();
  for (Eigen::Index k = 0; k < scale.size(); ++k)
    if (!(scale(k) > 0.0)) scale(k) = 1.0;  // an all-zero column: its singular value is dropped
  const Eigen::MatrixXd Js = J * scale.cwiseInverse().asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  Eigen::VectorXd utr = -svd.matrixU().transpose() * r0;
  rank = 0;
  for (Eigen::Index k = 0; k < sigma.size(); ++k) {
    if (sigma(k) > kSvdThreshold * sigma(0)) {
      utr(k) /= sigma(k);
      ++rank;
    } else {
      utr(k) = 0.0;
    }
  }
  return (svd.matrixV() * utr).cwiseQuotient(scale);
}

}  // namespace

ReissnerMindlinFit fit_reissner_mindlin(const Matrix6d& A, const Eigen::MatrixXd& H,
                                        const std::array<ShearRelaxation, 2>& S, double thickness,
                                        bool compat) {
  const FitProblem problem{A, S, thickness, compat};
  const int n = problem.unknowns();
  // r(x) = r0 + J x, with r0 the equations of H and column k of J those of coupling(e_k).
  const Eigen::VectorXd r0 = problem.equations(H);
  Eigen::MatrixXd J(r0.size(), n);
  for (int k = 0; k < n; ++k)
    J.col(k) = problem.equations(problem.coupling(Eigen::VectorXd::Unit(n, k)));

  ReissnerMindlinFit fit;
  int rank = 0;
  const Eigen::VectorXd x = solve_least_squares(J, r0, rank);
  fit.diagnostics.rank = rank;
  fit.diagnostics.unknowns = n;
  fit.diagnostics.equations = static_cast<int>(r0.size());
  const double r0_norm = r0.norm();
  fit.diagnostics.relative_residual = r0_norm > 0.0 ? (r0 + J * x).norm() / r0_norm : 0.0;

  const Matrix2d X = problem.X_of(x);  // symmetric by construction
  const double min_eigenvalue = Eigen::SelfAdjointEigenSolver<Matrix2d>(X).eigenvalues()(0);
  fit.diagnostics.X_min_eigenvalue = min_eigenvalue;
  if (!(min_eigenvalue > 0.0)) {
    std::ostringstream os;
    os << "the Reissner-Mindlin fit gave a transverse shear compliance X = G^-1 that is not "
          "positive definite (smallest eigenvalue "
       << min_eigenvalue << " mm/N); use the equilibrium shear stiffness instead";
    throw_numerical(os.str());
  }
  fit.G = X.inverse();
  fit.G = 0.5 * (fit.G + fit.G.transpose()).eval();
  return fit;
}

}  // namespace si
