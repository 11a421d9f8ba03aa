// Rigid flat-ended cylindrical punch of radius R with edge radius r_e (0 <= r_e < R): the
// Minkowski sum of a semi-infinite solid cylinder of radius R - r_e (ending in a flat disc) and
// a ball of radius r_e. Its flat face, of radius R - r_e, is centred at the pose position and
// faces the direction of travel; the body extends backwards. Exact, closed-form signed distance
// (exact inside too, as the core is convex). r_e = 0 is a sharp edge (distance not smooth there).
#pragma once

#include "contact/indenter.hpp"

namespace si {

class FlatPunchIndenter : public Indenter {
 public:
  FlatPunchIndenter(double radius, double edge_radius, const IndenterPose& pose);
  std::string name() const override { return "flat_punch"; }
  // The signed distance divided by R: the punch has no polynomial implicit form worth having.
  double implicit(const Vector3d& x, double travel) const override;
  double signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                         Matrix3d* hessian) const override;

 private:
  double radius_;
  double edge_radius_;
};

}  // namespace si
