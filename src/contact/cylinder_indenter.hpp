// Rigid cylinder of radius R whose axis (through the pose position, perpendicular to the
// direction of travel) gives line contact. length = 0: infinite; length L > 0: a straight part
// of length L with hemispherical ends (a capsule), which keeps the surface smooth.
// Exact signed distance: distance to the axis (segment) minus R.
#pragma once

#include "contact/indenter.hpp"

namespace si {

class CylinderIndenter : public Indenter {
 public:
  // `pose.axis` is made perpendicular to `pose.direction` and normalised.
  CylinderIndenter(double radius, double length, const IndenterPose& pose);
  std::string name() const override { return "cylinder"; }
  // (distance to the axis / R)^2 - 1, the cylinder's analogue of paper eq 29.
  double implicit(const Vector3d& x, double travel) const override;
  double signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                         Matrix3d* hessian) const override;
  const Vector3d& axis() const { return axis_; }

 private:
  // Closest point of the axis (segment) to x at `travel`; `on_straight` tells whether it is
  // inside the segment (not at an end).
  Vector3d closest_axis_point(const Vector3d& x, double travel, bool* on_straight) const;
  double radius_;
  double length_;
  Vector3d axis_;
};

}  // namespace si
