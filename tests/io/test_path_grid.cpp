// path_grid.csv (io/path_results.hpp): the fixed-depth table of a continuation run, interpolated
// between converged points. A synthetic branch whose apex deflection is a cubic and whose force
// and energy are a quadratic and a cubic in the depth (energy' = force, as at equilibrium), with
// exact depth slopes: cubic Hermite reproduces them to roundoff between points 0.7 mm apart,
// where linear interpolation errs by O(dh^2); the columns without slopes (contact radius) stay
// linear. (The CSV carries 12 significant digits: the tolerances.)
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "io/path_results.hpp"

namespace si {
namespace {

double force(double h) {
  return 100 * h + 30 * h * h;
}
double force_slope(double h) {
  return 100 + 60 * h;
}
double energy(double h) {
  return 50 * h * h + 10 * h * h * h;
}
double deflection(double h) {
  return 0.9 * h - 0.05 * h * h * h;
}
double deflection_slope(double h) {
  return 0.9 - 0.15 * h * h;
}

PathResult cubic_branch(const std::vector<double>& depths) {
  PathResult r;
  r.monitor_names = {"force_N",    "apex_w_mm",  "contact_radius_mm",
                     "k11_per_mm", "k12_per_mm", "k22_per_mm"};
  for (double h : depths) {
    PathPoint p;
    p.index = static_cast<int>(r.points.size());
    p.state.depth = h;
    p.state.force = force(h);
    p.state.apex_deflection = deflection(h);
    p.state.contact_radius = std::sqrt(h);
    p.state.energy = energy(h);
    p.depth_slopes.resize(6);
    p.depth_slopes << force_slope(h), deflection_slope(h), std::nan(""), 0, 0, 0;
    r.points.push_back(p);
  }
  return r;
}

// The rows of a path_grid.csv text: column -> value per row.
std::vector<std::vector<double>> rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> out;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    out.push_back(v);
  }
  return out;
}

TEST(PathGrid, CubicHermiteBetweenPointsWithDepthSlopes) {
  const PathResult r = cubic_branch({0.0, 0.7, 1.4, 2.1});
  const auto grid = rows(path_grid_csv(r, 0.1, 2.1));
  ASSERT_EQ(grid.size(), 22u);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const double h = 0.1 * static_cast<double>(k);
    const std::vector<double>& row = grid[k];
    EXPECT_NEAR(row[0], h, 1e-12);
    EXPECT_NEAR(row[1], force(h), 1e-9 * force(2.1)) << h;     // force_N: Hermite, exact
    EXPECT_NEAR(row[3], deflection(h), 1e-10) << h;            // apex_w_mm: Hermite, exact
    EXPECT_NEAR(row[10], energy(h), 1e-9 * energy(2.1)) << h;  // energy_Nmm: slope = force
    // contact_radius_mm: no slope, linear between the points that bracket h.
    const double a = 0.7 * std::floor(h / 0.7 + 1e-9), b = a + 0.7, t = (h - a) / 0.7;
    if (t > 1e-9) {
      EXPECT_NEAR(row[4], (1 - t) * std::sqrt(a) + t * std::sqrt(b), 1e-10) << h;
    }
    EXPECT_EQ(row.back(), t > 1e-9 ? 1.0 : 0.0) << h;  // interpolated / converged point
  }
  // The linear interpolation it replaces errs by O(dh^2) at mid-segment (0.35 mm: 3.7 N).
  const double linear = 0.5 * (force(0.0) + force(0.7));
  EXPECT_GT(std::abs(linear - force(0.35)), 1.0);
}

// Where a point has no slopes (a fold, or a run without them) the segment is linear.
TEST(PathGrid, LinearWhereASlopeIsUnknown) {
  PathResult r = cubic_branch({0.0, 0.7});
  r.points[1].depth_slopes[0] = std::nan("");
  const auto grid = rows(path_grid_csv(r, 0.35, 0.7));
  ASSERT_EQ(grid.size(), 3u);
  EXPECT_NEAR(grid[1][1], 0.5 * (force(0.0) + force(0.7)), 1e-9);
}

}  // namespace
}  // namespace si
