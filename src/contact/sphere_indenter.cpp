#include "contact/sphere_indenter.hpp"

#include "contact/offset_distance.hpp"

namespace si {

SphereIndenter::SphereIndenter(double radius, const IndenterPose& pose)
    : Indenter(pose), radius_(radius) {}

double SphereIndenter::implicit(const Vector3d& x, double travel) const {
  return (x - centre(travel)).squaredNorm() / (radius_ * radius_) - 1.0;
}

double SphereIndenter::signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                                       Matrix3d* hessian) const {
  return offset_distance(x, centre(travel), radius_, Matrix3d::Zero(), -pose().direction, normal,
                         hessian);
}

}  // namespace si
