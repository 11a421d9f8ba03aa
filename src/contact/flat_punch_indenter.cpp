#include "contact/flat_punch_indenter.hpp"

#include <algorithm>

#include "contact/offset_distance.hpp"

namespace si {

FlatPunchIndenter::FlatPunchIndenter(double radius, double edge_radius, const IndenterPose& pose)
    : Indenter(pose), radius_(radius), edge_radius_(edge_radius) {}

double FlatPunchIndenter::implicit(const Vector3d& x, double travel) const {
  return signed_distance(x, travel, nullptr, nullptr) / radius_;
}

// Cylindrical coordinates about the core disc's centre c (r_e behind the face): axial s along
// the direction of travel, radial rho. Core K = {s <= 0, rho <= R'} with R' = R - r_e.
double FlatPunchIndenter::signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                                          Matrix3d* hessian) const {
  const Vector3d& d = pose().direction;
  const double core_radius = radius_ - edge_radius_;
  const Vector3d c = pose().position + (travel - edge_radius_) * d;
  const Vector3d v = x - c;
  const double s = v.dot(d);
  const Vector3d w = v - s * d;
  const double rho = w.norm();
  const bool beyond_rim = rho > core_radius;
  const Matrix3d hoop = Matrix3d::Identity() - d * d.transpose() -
                        (rho > 0.0 ? Matrix3d(w * w.transpose() / (rho * rho)) : Matrix3d::Zero());
  // Outside the core beside its rim: nearest core point on the rim circle.
  if (s > 0.0 && beyond_rim) {
    const Vector3d rim = c + (core_radius / rho) * w;
    return offset_distance(x, rim, edge_radius_, (core_radius / rho) * hoop, d, normal, hessian);
  }
  // Beside the side wall or inside nearer the wall than the face: nearest point on the axis.
  if (beyond_rim || (s <= 0.0 && rho - core_radius > s)) {
    return offset_distance(x, c + s * d, core_radius + edge_radius_, d * d.transpose(), d, normal,
                           hessian);
  }
  // In front of the flat face, or inside nearer the face.
  if (normal) *normal = d;
  if (hessian) hessian->setZero();
  return s - edge_radius_;
}

}  // namespace si
