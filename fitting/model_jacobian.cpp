#include "fitting/model_jacobian.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace si::fit {

ModelJacobian model_jacobian(const ModelValues& model, const Eigen::VectorXd& c,
                             const Eigen::VectorXd& y0, const Eigen::VectorXd& lower,
                             const Eigen::VectorXd& upper, double relative_step,
                             DifferenceScheme scheme) {
  const Eigen::Index m = y0.size();
  const Eigen::Index n = c.size();
  ModelJacobian out;
  out.jacobian = Eigen::MatrixXd::Constant(m, n, std::numeric_limits<double>::quiet_NaN());
  out.steps = Eigen::VectorXd::Zero(n);
  out.central = Eigen::VectorXi::Zero(n);
  // y at `at`, evaluated at most once per point; empty when the model failed there.
  const auto evaluate = [&](const Eigen::VectorXd& at, std::optional<Eigen::VectorXd>& y) {
    if (y) return y->size() == m;
    ++out.evaluations;
    Eigen::VectorXd v(m);
    const bool ok = model(at, v) && v.size() == m && v.allFinite();
    y = ok ? v : Eigen::VectorXd();
    return ok;
  };
  for (Eigen::Index j = 0; j < n; ++j) {
    const double width = upper[j] - lower[j];
    const double h = std::min(relative_step * std::max(std::abs(c[j]), 0.01 * width), 0.25 * width);
    Eigen::VectorXd cp = c, cm = c;
    cp[j] = c[j] + h;
    cm[j] = c[j] - h;
    const bool up = cp[j] <= upper[j], down = cm[j] >= lower[j];
    std::optional<Eigen::VectorXd> yp, ym;
    const bool central = scheme == DifferenceScheme::kCentral;
    if (central && up && down && evaluate(cp, yp) && evaluate(cm, ym)) {
      // The step actually taken, (c + h) - (c - h), not 2h: removes the representation error.
      out.jacobian.col(j) = (*yp - *ym) / (cp[j] - cm[j]);
      out.steps[j] = h;
      out.central[j] = 1;
    } else if (up && evaluate(cp, yp)) {
      out.jacobian.col(j) = (*yp - y0) / (cp[j] - c[j]);
      out.steps[j] = h;
    } else if (down && evaluate(cm, ym)) {
      out.jacobian.col(j) = (y0 - *ym) / (c[j] - cm[j]);
      out.steps[j] = -h;
    } else {
      out.ok = false;
    }
  }
  return out;
}

}  // namespace si::fit
