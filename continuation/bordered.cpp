#include "continuation/bordered.hpp"

#include <cmath>

namespace si::cont {

bool BorderedSolver::setup(const Vector& x, double p) {
  if (!problem_.factorize(x, p)) return false;
  if (!problem_.residual_p(x, p, y2_) || y2_.size() != x.size()) return false;
  return problem_.solve(y2_) && y2_.allFinite();
}

double BorderedSolver::border_denominator(const Vector& c_x, double c_p) const {
  const double dot = c_x.size() == 0 ? 0.0 : problem_.inner(c_x, y2_);
  return weight_ * weight_ * c_p - dot;
}

bool BorderedSolver::solve(const Vector& c_x, double c_p, Vector& b, double beta, double& q) {
  if (!problem_.solve(b)) return false;  // b := y1
  const double denominator = border_denominator(c_x, c_p);
  const double dot = c_x.size() == 0 ? 0.0 : problem_.inner(c_x, b);
  q = (beta - dot) / denominator;
  if (!std::isfinite(q)) return false;
  b -= q * y2_;
  return b.allFinite();
}

bool BorderedSolver::tangent(const Vector& ref_x, double ref_p, Vector& t_x, double& t_p) {
  // b = 0, beta = 1: y1 = 0, so no solve is needed.
  const double q = 1.0 / border_denominator(ref_x, ref_p);
  if (!std::isfinite(q)) return false;
  t_x = -q * y2_;
  t_p = q;
  const double norm = std::sqrt(inner(t_x, t_p, t_x, t_p));
  if (!(norm > 0.0) || !std::isfinite(norm)) return false;
  t_x /= norm;
  t_p /= norm;
  return true;
}

}  // namespace si::cont
