#include "continuation/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace si::cont {

bool Problem::residual_p(const Vector& x, double p, Vector& out) {
  const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(p));
  Vector f_plus;
  Vector f_minus;
  if (!residual(x, p + h, f_plus) || !residual(x, p - h, f_minus)) return false;
  out = (f_plus - f_minus) / (2.0 * h);
  return true;
}

double Problem::inner(const Vector& a, const Vector& b) const {
  return a.dot(b);
}

std::vector<std::string> Problem::monitor_names() const {
  return {};
}

Vector Problem::monitors(const Vector& /*x*/, double /*p*/) {
  return Vector();
}

Vector Problem::monitor_subset(const Vector& x, double p, const std::vector<int>& which) {
  const Vector all = monitors(x, p);
  Vector out(static_cast<Eigen::Index>(which.size()));
  for (std::size_t i = 0; i < which.size(); ++i) out(static_cast<Eigen::Index>(i)) = all(which[i]);
  return out;
}

std::vector<int> Problem::signature(const Vector& /*x*/, double /*p*/) {
  return {};
}

int Problem::jacobian_sign() {
  return 0;
}

bool Problem::provides_stability() const {
  return false;
}

bool Problem::stability(const Vector& /*x*/, double /*p*/, int /*modes*/, Stability& /*out*/) {
  return false;
}

Vector Problem::corrector_start(const Vector& /*x_from*/, double /*p_from*/, double /*p*/) {
  return Vector();
}

bool Problem::adapt(Vector& /*x*/, double /*p*/) {
  return false;
}

void Problem::reset_solver_caches() {}

}  // namespace si::cont
