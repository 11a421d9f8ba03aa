#include "contact/indenter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace si {

double Indenter::min_distance(const std::vector<Vector3d>& points, double travel) const {
  double m = std::numeric_limits<double>::infinity();
  for (const Vector3d& x : points) m = std::min(m, signed_distance(x, travel, nullptr, nullptr));
  return m;
}

// Sphere tracing: an exact distance is 1-Lipschitz in the travel, so stepping by the smallest
// distance never passes the first touch (Hart 1996). A first-order distance (super-quadric) may
// overshoot: the step is then bracketed and bisected. A start inside is bracketed backwards.
double Indenter::first_touch(const std::vector<Vector3d>& points) const {
  if (points.empty()) throw_input("first touch of an empty point set");
  const std::optional<double> t = try_first_touch(points);
  if (!t) throw_input("the indenter never touches the points along its direction");
  return *t;
}

std::optional<double> Indenter::try_first_touch(const std::vector<Vector3d>& points) const {
  if (points.empty()) return std::nullopt;
  double scale = 1.0;
  for (const Vector3d& x : points) scale = std::max(scale, x.cwiseAbs().maxCoeff());
  const double tol = 1e-12 * scale;
  const int max_iter = 10000;

  double t = 0.0;
  double m = min_distance(points, t);
  for (double step = std::max(-m, tol); m < 0.0; step *= 2.0) {  // bracket a start inside
    t -= step;
    m = min_distance(points, t);
    if (step > 1e6 * scale) return std::nullopt;  // it never leaves them
  }
  for (int iter = 0; iter < max_iter && m > tol; ++iter) {
    const double t_next = t + m;
    const double m_next = min_distance(points, t_next);
    if (m_next < 0.0) {  // overshoot: bisect [t, t_next] keeping m(t) >= 0
      double hi = t_next;
      while (hi - t > tol) {
        const double mid = 0.5 * (t + hi);
        if (min_distance(points, mid) >= 0.0)
          t = mid;
        else
          hi = mid;
      }
      return t;
    }
    if (t_next > 1e6 * scale) break;
    t = t_next;
    m = m_next;
  }
  if (m > tol) return std::nullopt;
  return t;
}

}  // namespace si
