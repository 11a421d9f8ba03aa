#include "fitting/levenberg_marquardt.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace si::fit {
namespace {

Eigen::VectorXd project(const Eigen::VectorXd& c, const Eigen::VectorXd& lower,
                        const Eigen::VectorXd& upper) {
  Eigen::VectorXd p = c;
  if (lower.size() == c.size()) p = p.cwiseMax(lower);
  if (upper.size() == c.size()) p = p.cwiseMin(upper);
  return p;
}

// The largest cosine between the residual vector and a column of J: zero at a stationary point
// of the sum of squares, whatever the scaling (Moré, Garbow & Hillstrom 1980, MINPACK gtol).
// Parameters held by a bound that the descent direction pushes against are left out (the
// projected gradient of a bound-constrained minimum).
double gradient_cosine(const Eigen::MatrixXd& jac, const Eigen::VectorXd& r,
                       const Eigen::VectorXd& c, const Eigen::VectorXd& lower,
                       const Eigen::VectorXd& upper) {
  const double rn = r.norm();
  if (rn == 0.0) return 0.0;
  double worst = 0.0;
  for (Eigen::Index j = 0; j < jac.cols(); ++j) {
    const double g = jac.col(j).dot(r);  // half the derivative of S in c_j
    const bool held = (lower.size() == c.size() && c[j] <= lower[j] && g > 0.0) ||
                      (upper.size() == c.size() && c[j] >= upper[j] && g < 0.0);
    const double cn = jac.col(j).norm();
    if (cn > 0.0 && !held) worst = std::max(worst, std::abs(g) / (cn * rn));
  }
  return worst;
}

// The step d minimising |J d + r|^2 + lambda |D d|^2, by QR of the stacked matrix.
Eigen::VectorXd damped_step(const Eigen::MatrixXd& jac, const Eigen::VectorXd& r,
                            const Eigen::VectorXd& d, double lambda) {
  const Eigen::Index m = jac.rows();
  const Eigen::Index n = jac.cols();
  Eigen::MatrixXd a(m + n, n);
  a.topRows(m) = jac;
  a.bottomRows(n) = (std::sqrt(lambda) * d).asDiagonal();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m + n);
  b.head(m) = -r;
  return a.colPivHouseholderQr().solve(b);
}

// |D d| / |D c|: how far a step moves the parameters, relatively, in the norm scaled by D (Moré
// 1978, sec. 7), so that a parameter near zero (an offset that vanishes) does not count alone.
double relative_size(const Eigen::VectorXd& d, const Eigen::VectorXd& c, const Eigen::VectorXd& D) {
  const double size = D.cwiseProduct(c).norm();
  return size > 0.0 ? D.cwiseProduct(d).norm() / size : D.cwiseProduct(d).norm();
}

// Relative Gauss-Newton correction below which a point counts as converged when no step
// decreases S any more: sqrt(eps), the accuracy a double-precision minimum can be located to.
constexpr double kResolution = 1.5e-8;

std::string scientific(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0e", v);
  return buf;
}

}  // namespace

LevenbergMarquardtOutcome levenberg_marquardt(Evaluator& ev, const Eigen::VectorXd& start,
                                              const Eigen::VectorXd& lower,
                                              const Eigen::VectorXd& upper,
                                              const LevenbergMarquardtSettings& settings) {
  LevenbergMarquardtOutcome out;
  Eigen::VectorXd c = project(start, lower, upper);
  Eigen::VectorXd r = ev.residuals(c);
  double sse = ev.sum_of_squares(r);
  out.parameters = c;
  out.sse = sse;
  if (!std::isfinite(sse)) {
    out.reason = "residuals are not finite at the starting point";
    return out;
  }
  const int n = static_cast<int>(c.size());
  Eigen::VectorXd diag = Eigen::VectorXd::Zero(n);
  double lambda = 1e-3;
  constexpr double kLambdaMax = 1e20;
  for (int it = 1; it <= settings.max_iterations; ++it) {
    out.iterations = it;
    if (sse == 0.0) {
      out.converged = true;
      out.reason = "zero residual";
      return out;
    }
    const Eigen::MatrixXd jac = ev.jacobian(c);
    if (!jac.allFinite()) {
      out.reason = "the Jacobian is not finite";
      return out;
    }
    if (gradient_cosine(jac, r, c, lower, upper) <= settings.gradient_tol) {
      out.converged = true;
      out.reason = "residuals orthogonal to the Jacobian (gradient test)";
      return out;
    }
    diag = diag.cwiseMax(jac.colwise().norm().transpose());
    for (int j = 0; j < n; ++j)
      if (diag[j] == 0.0) diag[j] = 1.0;
    // Inner loop: raise the damping until a step decreases the sum of squares.
    while (true) {
      const Eigen::VectorXd trial = project(c + damped_step(jac, r, diag, lambda), lower, upper);
      const Eigen::VectorXd r_trial = ev.residuals(trial);
      const double sse_trial = ev.sum_of_squares(r_trial);
      if (sse_trial < sse) {
        const double move = relative_size(trial - c, trial, diag);
        c = trial;
        r = r_trial;
        sse = sse_trial;
        out.parameters = c;
        out.sse = sse;
        lambda = std::max(lambda / 3.0, 1e-15);
        if (move <= settings.xtol_rel) {
          out.converged = true;
          out.reason = "relative step below " + scientific(settings.xtol_rel);
          return out;
        }
        break;
      }
      lambda *= 4.0;
      if (lambda > kLambdaMax || c == trial) {
        // No decrease even along the steepest-descent direction: S is at its roundoff floor if
        // the gradient test nearly holds, or if the Gauss-Newton correction is below the
        // resolution double-precision data support (for data exact to 12 digits the residuals
        // are rounding noise, not orthogonal to J, yet the correction is ~1e-12 relative).
        const Eigen::VectorXd newton = project(c + damped_step(jac, r, diag, 0.0), lower, upper);
        out.converged =
            gradient_cosine(jac, r, c, lower, upper) <= std::sqrt(settings.gradient_tol) ||
            relative_size(newton - c, c, diag) <= kResolution;
        out.reason = out.converged ? "no further decrease possible (roundoff level)"
                                   : "no decrease along the damped steps";
        return out;
      }
    }
  }
  out.reason = "iteration limit (" + std::to_string(settings.max_iterations) + ") reached";
  return out;
}

}  // namespace si::fit
