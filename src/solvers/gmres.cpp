#include "solvers/gmres.hpp"

#include <cmath>
#include <vector>

namespace si {
namespace {

// One Givens rotation (c, s) that zeroes b in (a, b).
void givens(double a, double b, double& c, double& s) {
  const double r = std::hypot(a, b);
  c = r > 0 ? a / r : 1.0;
  s = r > 0 ? b / r : 0.0;
}

}  // namespace

GmresResult gmres(const LinearOperator& apply_a, const LinearOperator& apply_m_inverse,
                  const Eigen::VectorXd& b, Eigen::VectorXd& x, const GmresSettings& settings) {
  GmresResult out;
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    x.setZero(b.size());
    out.converged = true;
    return out;
  }
  const int m = settings.restart;
  const double target = settings.relative_tolerance * b_norm;
  Eigen::VectorXd r(b.size()), w(b.size()), z(b.size());
  std::vector<Eigen::VectorXd> v(m + 1);
  std::vector<Eigen::VectorXd> zs(m);  // preconditioned directions (right preconditioning)
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd g(m + 1), cs(m), sn(m);
  while (true) {
    apply_a(x, w);
    r = b - w;
    double beta = r.norm();
    out.relative_residual = beta / b_norm;
    if (beta <= target) {
      out.converged = true;
      return out;
    }
    if (out.iterations >= settings.max_iterations) return out;
    v[0] = r / beta;
    g.setZero();
    g[0] = beta;
    int k = 0;
    for (; k < m && out.iterations < settings.max_iterations; ++k) {
      apply_m_inverse(v[k], zs[k]);
      apply_a(zs[k], w);
      ++out.iterations;
      for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
        h(i, k) = v[i].dot(w);
        w -= h(i, k) * v[i];
      }
      h(k + 1, k) = w.norm();
      if (h(k + 1, k) > 0) v[k + 1] = w / h(k + 1, k);
      for (int i = 0; i < k; ++i) {  // previous rotations on the new column
        const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
        h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
        h(i, k) = t;
      }
      givens(h(k, k), h(k + 1, k), cs[k], sn[k]);
      h(k, k) = cs[k] * h(k, k) + sn[k] * h(k + 1, k);
      h(k + 1, k) = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      if (std::abs(g[k + 1]) <= target || h(k, k) == 0.0) {
        ++k;
        break;
      }
    }
    // x += Z y with H y = g (upper triangular k x k).
    const Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    for (int i = 0; i < k; ++i) x += y[i] * zs[i];
  }
}

}  // namespace si
