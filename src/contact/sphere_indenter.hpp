// Rigid sphere of radius R centred at the pose position (the paper's hemispherical indenter,
// eq 29 with x0 = the centre). Exact signed distance |x - c| - R.
#pragma once

#include "contact/indenter.hpp"

namespace si {

class SphereIndenter : public Indenter {
 public:
  SphereIndenter(double radius, const IndenterPose& pose);
  std::string name() const override { return "sphere"; }
  // Paper eq 29: |x - c|^2 / R^2 - 1.
  double implicit(const Vector3d& x, double travel) const override;
  double signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                         Matrix3d* hessian) const override;

 private:
  Vector3d centre(double travel) const { return pose().position + travel * pose().direction; }
  double radius_;
};

}  // namespace si
