#include "contact/superquadric_indenter.hpp"

#include <algorithm>
#include <cmath>

namespace si {
namespace {

// |t|^p and its first two derivatives.
struct Power {
  double value, first, second;
};

Power power(double t, double p) {
  const double at = std::abs(t);
  if (at == 0.0) return {0.0, 0.0, p == 2.0 ? 2.0 : 0.0};
  const double v = std::pow(at, p);
  return {v, p * v / t, p * (p - 1.0) * v / (at * at)};
}

}  // namespace

SuperquadricIndenter::SuperquadricIndenter(const SuperquadricShape& shape, const IndenterPose& pose)
    : Indenter(pose), shape_(shape) {}

double SuperquadricIndenter::implicit(const Vector3d& x, double travel) const {
  const double g = radial(x, travel, nullptr, nullptr);
  return std::pow(g + 1.0, 2.0 / shape_.e1) - 1.0;
}

// Derivatives in scaled coordinates u = X/a, v = Y/b, w = Z/c, then chained to x.
// F = A^r + |w|^q with A = |u|^p + |v|^p, p = 2/e2, q = 2/e1, r = e2/e1; g = F^(1/q) - 1.
double SuperquadricIndenter::radial(const Vector3d& x, double travel, Vector3d* grad,
                                    Matrix3d* hess) const {
  const double p = 2.0 / shape_.e2, q = 2.0 / shape_.e1, r = shape_.e2 / shape_.e1;
  const Vector3d scale(1.0 / shape_.a, 1.0 / shape_.b, 1.0 / shape_.c);
  const Vector3d s = (x - pose().position - travel * pose().direction).cwiseProduct(scale);
  const Power pu = power(s.x(), p), pv = power(s.y(), p), pw = power(s.z(), q);
  const double a_sum = pu.value + pv.value;
  const double f = std::pow(a_sum, r) + pw.value;
  if (!grad && !hess) return std::pow(f, 1.0 / q) - 1.0;

  Vector3d df = Vector3d::Zero();
  Matrix3d d2f = Matrix3d::Zero();
  if (a_sum > 0.0) {
    const Vector3d da(pu.first, pv.first, 0.0);
    const double ar1 = r * std::pow(a_sum, r - 1.0);
    df = ar1 * da;
    d2f = r * (r - 1.0) * std::pow(a_sum, r - 2.0) * da * da.transpose();
    d2f(0, 0) += ar1 * pu.second;
    d2f(1, 1) += ar1 * pv.second;
  }
  df.z() = pw.first;
  d2f(2, 2) = pw.second;
  if (f <= 0.0) {  // the centre: g = -1, no direction
    if (grad) grad->setZero();
    if (hess) hess->setZero();
    return -1.0;
  }
  const double fq = std::pow(f, 1.0 / q);
  const Vector3d dg = (fq / (q * f)) * df;
  if (grad) *grad = dg.cwiseProduct(scale);
  if (hess) {
    const Matrix3d d2g = (fq / (q * f)) * ((1.0 / q - 1.0) / f * df * df.transpose() + d2f);
    *hess = scale.asDiagonal() * d2g * scale.asDiagonal();
  }
  return fq - 1.0;
}

double SuperquadricIndenter::signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                                             Matrix3d* hessian) const {
  Vector3d dg;
  Matrix3d d2g;
  const double g = radial(x, travel, &dg, &d2g);
  const double len = dg.norm();
  if (len == 0.0) {  // the centre: deepest point, direction undefined
    if (normal) *normal = -pose().direction;
    if (hessian) hessian->setZero();
    return -std::min({shape_.a, shape_.b, shape_.c});
  }
  const Vector3d n = dg / len;
  if (normal) *normal = n;
  if (hessian) *hessian = (Matrix3d::Identity() - n * n.transpose()) * d2g / len;
  return g / len;
}

}  // namespace si
