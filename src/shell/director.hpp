#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/linalg.hpp"

namespace si {

struct NodeState {
  Vector3d u;
  Vector3d d;
  Vector3d v1;
  Vector3d v2;
};  // current displacement, current unit director, current rotation axes
NodeState reference_node_state(
    const Vector3d& D);  // u = 0, d = D, v1 = (e2 x D)/|e2 x D| (e3 if D || e2), v2 = D x v1
void rotate_node(NodeState&, double a,
                 double b);  // d, v1, v2 <- exp(skew(a v1 + b v2)) (d, v1, v2)  (Rodrigues)

}  // namespace si
