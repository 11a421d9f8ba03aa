#include "contact/cylinder_indenter.hpp"

#include <algorithm>

#include "contact/offset_distance.hpp"
#include "core/error.hpp"

namespace si {

CylinderIndenter::CylinderIndenter(double radius, double length, const IndenterPose& pose)
    : Indenter(pose), radius_(radius), length_(length) {
  const Vector3d& d = pose.direction;
  axis_ = pose.axis - pose.axis.dot(d) * d;
  SI_REQUIRE(axis_.norm() > 1e-8 * pose.axis.norm() && axis_.norm() > 0.0,
             "indenter: the cylinder axis must not be parallel to the direction of travel");
  axis_.normalize();
}

Vector3d CylinderIndenter::closest_axis_point(const Vector3d& x, double travel,
                                              bool* on_straight) const {
  const Vector3d c = pose().position + travel * pose().direction;
  double s = (x - c).dot(axis_);
  *on_straight = true;
  if (length_ > 0.0 && std::abs(s) >= 0.5 * length_) {
    s = std::clamp(s, -0.5 * length_, 0.5 * length_);
    *on_straight = false;
  }
  return c + s * axis_;
}

double CylinderIndenter::implicit(const Vector3d& x, double travel) const {
  bool on_straight = true;
  return (x - closest_axis_point(x, travel, &on_straight)).squaredNorm() / (radius_ * radius_) -
         1.0;
}

double CylinderIndenter::signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                                         Matrix3d* hessian) const {
  bool on_straight = true;
  const Vector3d p = closest_axis_point(x, travel, &on_straight);
  const Matrix3d core = on_straight ? Matrix3d(axis_ * axis_.transpose()) : Matrix3d::Zero();
  return offset_distance(x, p, radius_, core, -pose().direction, normal, hessian);
}

}  // namespace si
