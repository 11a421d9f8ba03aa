#include "fitting/builtin_models.hpp"

#include <cmath>
#include <vector>

#include "fitting/linear_fit.hpp"

namespace si::fit {
namespace {

// x^p and its derivative in p, x^p ln x, with the limits at x = 0 (p > 0: both 0).
double power(double x, double p) {
  if (x != 0.0) return std::pow(x, p);
  return p > 0.0 ? 0.0 : p == 0.0 ? 1.0 : HUGE_VAL;
}
double power_log(double x, double p) {
  return x == 0.0 ? 0.0 : std::pow(x, p) * std::log(x);
}

// C1, C2 of a power law through the points with x > 0 and y - offset > 0, from a straight line in
// log-log coordinates; (max y / max x, 1) if fewer than two such points with distinct x.
Eigen::Vector2d loglog_guess(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double offset) {
  std::vector<double> xs;
  std::vector<double> ys;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (x[i] > 0.0 && y[i] - offset > 0.0) {
      xs.push_back(x[i]);
      ys.push_back(y[i] - offset);
    }
  const Eigen::Map<Eigen::VectorXd> px(xs.data(), static_cast<Eigen::Index>(xs.size()));
  const Eigen::Map<Eigen::VectorXd> py(ys.data(), static_cast<Eigen::Index>(ys.size()));
  if (xs.size() >= 2 && px.maxCoeff() > px.minCoeff()) {
    const FitResult f = fit_power_law_log(px, py);
    if (f.parameters.allFinite()) return f.parameters;
  }
  const double xmax = x.size() ? x.cwiseAbs().maxCoeff() : 1.0;
  const double ymax = y.size() ? y.cwiseAbs().maxCoeff() : 1.0;
  return {xmax > 0 && ymax > 0 ? ymax / xmax : 1.0, 1.0};
}

}  // namespace

CurveModel power_law() {
  CurveModel m;
  m.name = "power";
  m.formula = "y = C1 * x^C2";
  m.parameter_names = {"C1", "C2"};
  m.min_x = 0.0;
  m.value = [](double x, const Eigen::VectorXd& c) { return c[0] * power(x, c[1]); };
  m.gradient = [](double x, const Eigen::VectorXd& c, Eigen::Ref<Eigen::VectorXd> g) {
    g[0] = power(x, c[1]);
    g[1] = c[0] * power_log(x, c[1]);
  };
  m.start = [](const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
    return Eigen::VectorXd(loglog_guess(x, y, 0.0));
  };
  return m;
}

CurveModel hertz_law() {
  CurveModel m;
  m.name = "hertz";
  m.formula = "y = C * x^1.5";
  m.parameter_names = {"C"};
  m.min_x = 0.0;
  m.value = [](double x, const Eigen::VectorXd& c) { return c[0] * x * std::sqrt(x); };
  m.gradient = [](double x, const Eigen::VectorXd&, Eigen::Ref<Eigen::VectorXd> g) {
    g[0] = x * std::sqrt(x);
  };
  // Linear in C: the least-squares C = sum y x^1.5 / sum x^3 is the answer itself.
  m.start = [](const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
    const Eigen::ArrayXd b = x.array() * x.array().sqrt();
    const double den = (b * b).sum();
    return Eigen::VectorXd::Constant(1, den > 0 ? (b * y.array()).sum() / den : 1.0).eval();
  };
  return m;
}

CurveModel power_law_with_offset() {
  CurveModel m;
  m.name = "power-offset";
  m.formula = "y = C1 * x^C2 + C0";
  m.parameter_names = {"C1", "C2", "C0"};
  m.min_x = 0.0;
  m.value = [](double x, const Eigen::VectorXd& c) { return c[0] * power(x, c[1]) + c[2]; };
  m.gradient = [](double x, const Eigen::VectorXd& c, Eigen::Ref<Eigen::VectorXd> g) {
    g[0] = power(x, c[1]);
    g[1] = c[0] * power_log(x, c[1]);
    g[2] = 1.0;
  };
  // Offset: y at the smallest x; the power law through the points above it.
  m.start = [](const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
    Eigen::VectorXd c(3);
    Eigen::Index i0 = 0;
    if (x.size() == 0) return Eigen::VectorXd::Ones(3).eval();
    x.minCoeff(&i0);
    const double offset = y[i0];
    c << loglog_guess(x, y, offset), offset;
    return c;
  };
  return m;
}

}  // namespace si::fit
