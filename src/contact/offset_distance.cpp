#include "contact/offset_distance.hpp"

namespace si {

double offset_distance(const Vector3d& x, const Vector3d& p, double r,
                       const Matrix3d& core_curvature, const Vector3d& fallback, Vector3d* normal,
                       Matrix3d* hessian) {
  const Vector3d v = x - p;
  const double len = v.norm();
  const bool degenerate = len <= 1e-14 * (1.0 + r);
  const Vector3d n = degenerate ? fallback : Vector3d(v / len);
  if (normal) *normal = n;
  if (hessian)
    *hessian = degenerate
                   ? Matrix3d::Zero()
                   : Matrix3d((Matrix3d::Identity() - n * n.transpose() - core_curvature) / len);
  return len - r;
}

}  // namespace si
