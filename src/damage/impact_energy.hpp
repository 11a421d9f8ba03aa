// Quasi-static equivalence of a low-velocity impact (Nettles & Douglas, "A comparison of
// quasi-static indentation to low-velocity impact", NASA/TP-2000-210481): an impact of energy E
// does the damage a quasi-static indentation does when the indenter's work reaches E. Given a
// force-depth path, these functions find the depth and force where the work equals E, with the
// force interpolated between the path's points in the same way as the work is integrated, so
// that the reported point's work is E exactly (to round-off):
//   kTrapezoid: force linear in depth on each segment; the work is the trapezoidal sum that
//               path.csv's work_Nmm column holds, quadratic within a segment;
//   kHermite:   force cubic Hermite with the points' slopes dF/dh (as path_grid.csv); the work is
//               its exact integral, quartic within a segment.
// Segments are taken in path order, so a path whose depth turns back (snap-back) is followed as
// computed; the first point along the path whose work equals E is returned. An energy above the
// largest work on the path is reported as beyond the path, never extrapolated.
#pragma once

#include <vector>

namespace si {

enum class WorkInterpolation { kTrapezoid, kHermite };

struct ForceDepthPath {
  std::vector<double> depth;  // mm, in path order
  std::vector<double> force;  // N
  std::vector<double> slope;  // dF/dh at the points, N/mm (kHermite only)
};

enum class EnergyOutcome { kReached, kBeyondPath };

struct EnergyPoint {
  double energy = 0;  // the impact energy asked for, N mm
  EnergyOutcome outcome = EnergyOutcome::kBeyondPath;
  double depth = 0;     // where the work equals the energy (kReached; NaN beyond the path)
  double force = 0;     // N, the interpolated force there (NaN beyond the path)
  int segment = -1;     // between points segment and segment + 1 (-1 beyond the path)
  double max_work = 0;  // the largest work anywhere on the path, N mm
};

// The work at every point of the path (0 at the first), integrated as `interpolation` says.
// Throws an input si::Error for a path with fewer than two points, sizes that differ, or missing
// slopes for kHermite.
std::vector<double> path_work(const ForceDepthPath& path, WorkInterpolation interpolation);

// Throws an input si::Error for a negative or non-finite energy (key "impact_energy").
EnergyPoint depth_at_energy(const ForceDepthPath& path, double energy,
                            WorkInterpolation interpolation);
std::vector<EnergyPoint> depths_at_energies(const ForceDepthPath& path,
                                            const std::vector<double>& energies,
                                            WorkInterpolation interpolation);

}  // namespace si
