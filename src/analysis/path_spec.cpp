#include "analysis/path_spec.hpp"

#include <algorithm>
#include <cmath>

namespace si {

std::vector<double> depth_grid(const PathSpec& path) {
  if (!path.depths.empty()) return path.depths;
  std::vector<double> grid;
  const int n = static_cast<int>(std::ceil(path.depth_max / path.step - 1e-9));
  for (int i = 1; i <= n; ++i) grid.push_back(std::min(path.depth_max, i * path.step));
  return grid;
}

}  // namespace si
