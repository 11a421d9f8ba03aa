// Rigid indenters as implicit surfaces: the interface shared by every shape (sphere,
// super-quadric, flat punch, cylinder). Theory, frames and sign conventions:
// docs/theory/indenters.md; the paper's eqs 29-32 (super-quadric surface, contact test, normal).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/linalg.hpp"

namespace si {

// Where the indenter is at travel 0 and where it goes.
struct IndenterPose {
  Vector3d position = Vector3d::Zero();  // reference point: sphere/super-quadric/cylinder centre,
                                         // flat punch: centre of the flat face (the tip)
  Vector3d direction{0, 0, -1};          // unit direction of travel
  Vector3d axis{0, 1, 0};  // cylinder only: its axis, made perpendicular to `direction`
};

class Indenter {
 public:
  virtual ~Indenter() = default;
  virtual std::string name() const = 0;
  // Where it starts and where it goes. The line through pose().position along the direction of
  // travel is the indenter's axis (the contact's axis for a sphere).
  const IndenterPose& pose() const { return pose_; }

  // Implicit function f(x) of the indenter moved by `travel` along its direction: f < 0 inside,
  // f = 0 on the surface, f > 0 outside (paper eq 29 for the super-quadric).
  virtual double implicit(const Vector3d& x, double travel) const = 0;

  // Signed distance to the surface (> 0 outside). `normal` (optional) receives the outward unit
  // normal (the gradient of the distance); `hessian` (optional) the derivative of that normal
  // with respect to x, which is the Hessian of the distance when the distance is exact.
  virtual double signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                                 Matrix3d* hessian) const = 0;

  // Travel at which the indenter first touches `points`: the largest travel with every signed
  // distance >= 0. Negative when the indenter starts inside the points' convex region.
  // Throws an input Error when the points are empty or never touched.
  double first_touch(const std::vector<Vector3d>& points) const;
  // The same without the error: no value when the points are empty or never touched (the
  // candidate searches ask it of every node beside the indenter's path, at every point).
  std::optional<double> try_first_touch(const std::vector<Vector3d>& points) const;

  // Smallest signed distance of `points` at `travel`.
  double min_distance(const std::vector<Vector3d>& points, double travel) const;

 protected:
  explicit Indenter(const IndenterPose& pose) : pose_(pose) {}

 private:
  IndenterPose pose_;
};

}  // namespace si
