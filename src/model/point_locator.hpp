// Finds points that coincide within a tolerance, in O(log n) per query: points are binned in
// cubic cells of the tolerance's size, so a match can only sit in the 27 cells around a query.
// Used to merge the nodes of mesh blocks and to detect unmerged duplicate nodes.
#pragma once

#include <array>
#include <map>
#include <vector>

#include "core/linalg.hpp"

namespace si {

class PointLocator {
 public:
  explicit PointLocator(double tolerance);

  // Index of a stored point within the tolerance of p (the lowest such index), or -1.
  int find(const Vector3d& p) const;
  void insert(const Vector3d& p, int index);

 private:
  using Cell = std::array<long long, 3>;
  Cell cell_of(const Vector3d& p) const;

  double tolerance_;
  std::map<Cell, std::vector<std::pair<Vector3d, int>>> cells_;
};

}  // namespace si
