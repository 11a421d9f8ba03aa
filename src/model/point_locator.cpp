#include "model/point_locator.hpp"

#include <cmath>

#include "core/error.hpp"

namespace si {

PointLocator::PointLocator(double tolerance) : tolerance_(tolerance) {
  SI_REQUIRE(tolerance > 0 && std::isfinite(tolerance), "point tolerance must be positive");
}

PointLocator::Cell PointLocator::cell_of(const Vector3d& p) const {
  // Cell indices must fit a long long (and converting a larger double would be undefined).
  if (!(p.cwiseAbs().maxCoeff() / tolerance_ < 1e15)) {
    throw_input("a point is too far from the origin, or not finite, for a tolerance of " +
                std::to_string(tolerance_));
  }
  return {static_cast<long long>(std::floor(p.x() / tolerance_)),
          static_cast<long long>(std::floor(p.y() / tolerance_)),
          static_cast<long long>(std::floor(p.z() / tolerance_))};
}

int PointLocator::find(const Vector3d& p) const {
  const Cell c = cell_of(p);
  int best = -1;
  for (long long dx = -1; dx <= 1; ++dx) {
    for (long long dy = -1; dy <= 1; ++dy) {
      for (long long dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
        if (it == cells_.end()) continue;
        for (const auto& [q, index] : it->second) {
          if ((q - p).norm() <= tolerance_ && (best < 0 || index < best)) best = index;
        }
      }
    }
  }
  return best;
}

void PointLocator::insert(const Vector3d& p, int index) {
  cells_[cell_of(p)].push_back({p, index});
}

}  // namespace si
