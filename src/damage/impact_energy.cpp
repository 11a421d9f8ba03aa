#include "damage/impact_energy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace si {
namespace {

// One segment of the path, parametrised by s in [0, 1]: h = h0 + s dh.
struct Segment {
  double h0, dh, F0, F1, m0, m1;  // m: dF/dh at the ends
  WorkInterpolation interpolation;

  double force(double s) const {
    if (interpolation == WorkInterpolation::kTrapezoid) return F0 + s * (F1 - F0);
    const double s2 = s * s, s3 = s2 * s;  // cubic Hermite basis
    return (2 * s3 - 3 * s2 + 1) * F0 + (s3 - 2 * s2 + s) * dh * m0 + (-2 * s3 + 3 * s2) * F1 +
           (s3 - s2) * dh * m1;
  }
  // Work done from s = 0 to s: dh times the integral of the force over s.
  double work(double s) const {
    if (interpolation == WorkInterpolation::kTrapezoid)
      return dh * (F0 * s + 0.5 * (F1 - F0) * s * s);
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;  // integrals of the Hermite basis
    return dh * ((s - s3 + 0.5 * s4) * F0 + (0.5 * s2 - 2 * s3 / 3 + 0.25 * s4) * dh * m0 +
                 (s3 - 0.5 * s4) * F1 + (-s3 / 3 + 0.25 * s4) * dh * m1);
  }
};

void validate(const ForceDepthPath& path, WorkInterpolation interpolation) {
  const size_t n = path.depth.size();
  if (n < 2 || path.force.size() != n)
    throw_input("a force-depth path needs at least two points with one force per depth");
  if (interpolation == WorkInterpolation::kHermite && path.slope.size() != n)
    throw_input("Hermite interpolation of a force-depth path needs the slope dF/dh at every point");
}

Segment segment(const ForceDepthPath& p, size_t i, WorkInterpolation interpolation) {
  const bool hermite = interpolation == WorkInterpolation::kHermite;
  return {p.depth[i],     p.depth[i + 1] - p.depth[i], p.force[i],
          p.force[i + 1], hermite ? p.slope[i] : 0.0,  hermite ? p.slope[i + 1] : 0.0,
          interpolation};
}

// The first s in [0, 1] where W0 + work(s) = E, or -1 if there is none: the first sign change on
// a subdivision of the segment, then bisection to round-off. The work is a quadratic (trapezoid)
// or quartic (Hermite) in s and need not be monotone where the force changes sign; a touch without
// a sign change inside one sixteenth of a segment is not seen.
double first_crossing(const Segment& seg, double W0, double E) {
  auto g = [&](double s) { return W0 + seg.work(s) - E; };
  constexpr int kSubdivisions = 16;
  double a = 0, ga = g(0);
  if (ga == 0) return 0;
  for (int k = 1; k <= kSubdivisions; ++k) {
    double b = static_cast<double>(k) / kSubdivisions, gb = g(b);
    if (gb == 0) return b;
    if ((ga < 0) != (gb < 0)) {
      for (int it = 0; it < 200 && b - a > 4 * std::numeric_limits<double>::epsilon(); ++it) {
        const double m = 0.5 * (a + b), gm = g(m);
        if ((ga < 0) == (gm < 0)) {
          a = m;
          ga = gm;
        } else {
          b = m;
        }
      }
      return std::abs(ga) <= std::abs(g(b)) ? a : b;
    }
    a = b;
    ga = gb;
  }
  return -1;  // no crossing on this segment
}

}  // namespace

std::vector<double> path_work(const ForceDepthPath& path, WorkInterpolation interpolation) {
  validate(path, interpolation);
  std::vector<double> W{0.0};
  for (size_t i = 0; i + 1 < path.depth.size(); ++i)
    W.push_back(W.back() + segment(path, i, interpolation).work(1.0));
  return W;
}

EnergyPoint depth_at_energy(const ForceDepthPath& path, double energy,
                            WorkInterpolation interpolation) {
  if (!(energy >= 0) || !std::isfinite(energy)) {
    std::ostringstream os;
    os << energy << " N*mm";
    throw_input("an impact energy must be a non-negative number",
                Where{"", "impact_energy", os.str(), 0});
  }
  const std::vector<double> W = path_work(path, interpolation);
  EnergyPoint out;
  out.energy = energy;
  out.max_work = *std::max_element(W.begin(), W.end());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.depth = out.force = nan;
  for (size_t i = 0; i + 1 < path.depth.size(); ++i) {
    const Segment seg = segment(path, i, interpolation);
    const double s = first_crossing(seg, W[i], energy);
    if (s < 0) continue;
    out.outcome = EnergyOutcome::kReached;
    out.segment = static_cast<int>(i);
    out.depth = seg.h0 + s * seg.dh;
    out.force = seg.force(s);
    return out;
  }
  return out;
}

std::vector<EnergyPoint> depths_at_energies(const ForceDepthPath& path,
                                            const std::vector<double>& energies,
                                            WorkInterpolation interpolation) {
  std::vector<EnergyPoint> out;
  for (double e : energies) out.push_back(depth_at_energy(path, e, interpolation));
  return out;
}

}  // namespace si
