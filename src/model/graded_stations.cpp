#include "model/graded_stations.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace si {

std::vector<double> graded_stations(double s0, double s1,
                                    const std::function<double(double)>& size) {
  const int samples = 2000;
  std::vector<double> s(samples + 1), count(samples + 1, 0.0);
  for (int k = 0; k <= samples; ++k) s[k] = s0 + (s1 - s0) * k / samples;
  for (int k = 1; k <= samples; ++k) {
    count[k] = count[k - 1] + 0.5 * (1 / size(s[k - 1]) + 1 / size(s[k])) * (s[k] - s[k - 1]);
  }
  const int m = std::max(1, static_cast<int>(std::lround(count.back())));
  std::vector<double> stations{s0};
  int k = 1;
  for (int i = 1; i < m; ++i) {
    const double wanted = count.back() * i / m;
    while (count[k] < wanted) ++k;
    const double f = (wanted - count[k - 1]) / (count[k] - count[k - 1]);
    stations.push_back(s[k - 1] + f * (s[k] - s[k - 1]));
  }
  stations.push_back(s1);
  return stations;
}

std::vector<double> centred_graded_stations(double length, const LineGrading& g) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!positive(g.size_center) || g.size_center > length)
    throw_input("the element size at the indentation point must be positive and at most " +
                    std::to_string(length) + " mm (the distance to the edge)",
                {"", "size_apex", std::to_string(g.size_center)});
  if (!positive(g.size_edge))
    throw_input("must be positive", {"", "size_edge", std::to_string(g.size_edge)});
  if (g.size_center > g.size_edge)
    throw_input(
        "a graded mesh refines towards the indentation point: size_apex must not exceed "
        "size_edge (" +
            std::to_string(g.size_edge) + " mm)",
        {"", "size_apex", std::to_string(g.size_center)});
  if (!positive(g.refine_radius))
    throw_input("must be positive", {"", "refine_radius", std::to_string(g.refine_radius)});
  const auto size = [&](double s) {
    if (s <= g.refine_radius || g.refine_radius >= length) return g.size_center;
    return g.size_center +
           (s - g.refine_radius) / (length - g.refine_radius) * (g.size_edge - g.size_center);
  };
  return graded_stations(0.0, length, size);
}

std::vector<double> mirrored(const std::vector<double>& half) {
  std::vector<double> out;
  for (auto it = half.rbegin(); it != half.rend(); ++it) out.push_back(-*it);
  out.back() = half.front();  // the centre itself, not its negative (-0)
  out.insert(out.end(), half.begin() + 1, half.end());
  return out;
}

}  // namespace si
