#include "contact/travel_gap.hpp"

#include <cmath>
#include <optional>

namespace si {
namespace {

// Newton on phi(p, t) = 0 (d phi / dt = -n.e). Returns false if it leaves the arriving side.
bool newton_travel(const Indenter& indenter, const Vector3d& e, const Vector3d& p, double& t) {
  const double tol = 1e-14 * (1.0 + std::abs(t) + p.cwiseAbs().maxCoeff());
  for (int iter = 0; iter < 60; ++iter) {
    Vector3d n;
    const double phi = indenter.signed_distance(p, t, &n, nullptr);
    const double ne = n.dot(e);
    if (!(ne > kGrazingCosine) || !std::isfinite(phi)) return false;
    const double dt = phi / ne;
    t += dt;
    if (std::abs(dt) <= tol) return true;
  }
  return false;
}

}  // namespace

TravelGap travel_gap(const Indenter& indenter, const Vector3d& direction, const Vector3d& p,
                     double guess, bool want_hessian) {
  TravelGap g;
  double t = guess;
  if (!newton_travel(indenter, direction, p, t)) {
    const std::optional<double> touch = indenter.try_first_touch({p});
    if (!touch) return g;  // the indenter never reaches p along its path
    t = *touch;
    if (!newton_travel(indenter, direction, p, t)) return g;
  }
  Vector3d n;
  Matrix3d H;
  indenter.signed_distance(p, t, &n, want_hessian ? &H : nullptr);
  const double ne = n.dot(direction);
  if (!(ne > kGrazingCosine)) return g;
  g.hits = true;
  g.travel = t;
  g.gradient = n / ne;
  if (want_hessian) {
    const Matrix3d Q = Matrix3d::Identity() - direction * n.transpose() / ne;
    g.hessian = Q.transpose() * H * Q / ne;
  }
  return g;
}

}  // namespace si
