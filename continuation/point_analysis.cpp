#include "continuation/point_analysis.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace si::cont {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The monitors in `which` at u + h du (du = (dx, dp)).
Vector monitors_at(Problem& problem, const Point& pt, const Vector& dx, double dp, double h,
                   const std::vector<int>& which) {
  return problem.monitor_subset(pt.x + h * dx, pt.p + h * dp, which);
}

// A full-length monitor vector: NaN except at `which`, whose values are `subset`'s.
Vector scattered(const Vector& subset, const std::vector<int>& which, Eigen::Index size) {
  Vector out = Vector::Constant(size, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < which.size(); ++i)
    out(which[i]) = subset(static_cast<Eigen::Index>(i));
  return out;
}

// Second derivative of the branch u'' = (x'', p''), from F_uu[t, t] by a second difference with
// step h (f_zero = F at the point).
bool branch_curvature(Problem& problem, BorderedSolver& bordered, const TangentPoint& tp,
                      const Vector& f_zero, double h, Vector& xpp, double& ppp) {
  const Point& pt = tp.point;
  Vector f_plus;
  Vector f_minus;
  if (!problem.residual(pt.x + h * tp.tangent_x, pt.p + h * pt.tangent_p, f_plus) ||
      !problem.residual(pt.x - h * tp.tangent_x, pt.p - h * pt.tangent_p, f_minus))
    return false;
  xpp = -(f_plus - 2.0 * f_zero + f_minus) / (h * h);
  return bordered.solve(tp.tangent_x, pt.tangent_p, xpp, 0.0, ppp);
}

// m'' of the monitors in `which` (m0: their values at the point) and p'', with second-difference
// step h2 (first differences along u'' with h1). false when u'' cannot be computed.
bool second_derivatives(Problem& problem, BorderedSolver& bordered, const TangentPoint& tp,
                        const Vector& f_zero, const std::vector<int>& which, const Vector& m0,
                        double h1, double h2, Vector& mpp, double& ppp) {
  const Point& pt = tp.point;
  const Vector& t = tp.tangent_x;
  mpp = (monitors_at(problem, pt, t, pt.tangent_p, h2, which) - 2.0 * m0 +
         monitors_at(problem, pt, t, pt.tangent_p, -h2, which)) /
        (h2 * h2);
  Vector xpp;
  if (!branch_curvature(problem, bordered, tp, f_zero, h2, xpp, ppp)) return false;
  // grad m . u'' by a central difference along the unit vector u'' / |u''|.
  const double size = std::sqrt(bordered.inner(xpp, ppp, xpp, ppp));
  if (size > 0.0 && std::isfinite(size)) {
    const Vector e_x = xpp / size;
    const double e_p = ppp / size;
    mpp += size *
           (monitors_at(problem, pt, e_x, e_p, h1, which) -
            monitors_at(problem, pt, e_x, e_p, -h1, which)) /
           (2.0 * h1);
  }
  return true;
}

void monitor_derivatives(Problem& problem, BorderedSolver& bordered, const AnalysisNeeds& needs,
                         TangentPoint& tp) {
  Point& pt = tp.point;
  const std::vector<int>& which = needs.derivative_monitors;
  const Eigen::Index n = pt.monitors.size();
  const double scale = 1.0 + std::sqrt(bordered.inner(pt.x, pt.p, pt.x, pt.p));
  const double h1 = std::cbrt(kEps) * scale;
  const double h2 = std::sqrt(std::sqrt(kEps)) * scale;
  const Vector& t = tp.tangent_x;
  const double tp_p = pt.tangent_p;
  const Vector slopes = (monitors_at(problem, pt, t, tp_p, h1, which) -
                         monitors_at(problem, pt, t, tp_p, -h1, which)) /
                        (2.0 * h1);
  pt.monitor_slopes = scattered(slopes, which, n);
  if (!(needs.curvatures || needs.curvature_errors)) return;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Vector m0(static_cast<Eigen::Index>(which.size()));
  for (std::size_t i = 0; i < which.size(); ++i)
    m0(static_cast<Eigen::Index>(i)) = pt.monitors(which[i]);
  Vector f_zero;
  Vector mpp;
  double ppp = 0.0;
  if (!problem.residual(pt.x, pt.p, f_zero) ||
      !second_derivatives(problem, bordered, tp, f_zero, which, m0, h1, h2, mpp, ppp)) {
    pt.monitor_curvatures = Vector::Constant(n, nan);
    return;
  }
  pt.monitor_curvatures = scattered(mpp, which, n);
  if (!needs.curvature_errors) return;
  Vector mpp_coarse;
  double ppp_coarse = 0.0;
  pt.parameter_curvature = ppp;
  if (!second_derivatives(problem, bordered, tp, f_zero, which, m0, h1, 2.0 * h2, mpp_coarse,
                          ppp_coarse)) {
    pt.monitor_curvature_errors = Vector::Constant(n, nan);
    pt.parameter_curvature_error = nan;
    return;
  }
  const Vector roundoff = 4.0 * kEps * m0.cwiseAbs() / (h2 * h2);
  pt.monitor_curvature_errors =
      scattered((mpp - mpp_coarse).cwiseAbs().cwiseMax(roundoff), which, n);
  pt.parameter_curvature_error = std::abs(ppp - ppp_coarse);
}

bool add_stability(Problem& problem, int modes, TangentPoint& tp) {
  Stability s;
  if (!problem.stability(tp.point.x, tp.point.p, modes, s)) return false;
  Point& pt = tp.point;
  pt.negative_eigenvalues = s.negative;
  pt.zero_eigenvalues = s.zero;
  pt.stable = s.negative == 0 && s.zero == 0;
  pt.eigenvalues = s.eigenvalues;
  if (s.eigenvalues.size() > 0) pt.lowest_eigenvalue = s.eigenvalues(0);
  tp.modes = std::move(s.modes);
  return true;
}

}  // namespace

bool analyse_point(Problem& problem, BorderedSolver& bordered, const Vector& x, double p,
                   const Vector& ref_x, double ref_p, const AnalysisNeeds& needs,
                   TangentPoint& out) {
  TangentPoint tp;
  Point& pt = tp.point;
  pt.x = x;
  pt.p = p;
  if (!needs.tangent) {
    pt.monitors = problem.monitors(x, p);
    pt.signature = needs.signature ? problem.signature(x, p) : std::vector<int>{};
    out = std::move(tp);
    return true;
  }
  if (!bordered.setup(x, p)) return false;
  pt.jacobian_sign = problem.jacobian_sign();
  const Vector ref = ref_x.size() == x.size() ? ref_x : Vector();
  if (!bordered.tangent(ref, ref_p, tp.tangent_x, pt.tangent_p)) return false;
  pt.monitors = problem.monitors(x, p);
  if (needs.slopes || needs.curvatures || needs.curvature_errors)
    monitor_derivatives(problem, bordered, needs, tp);
  pt.signature = needs.signature ? problem.signature(x, p) : std::vector<int>{};
  if (needs.stability_modes > 0 && !add_stability(problem, needs.stability_modes, tp)) return false;
  out = std::move(tp);
  return true;
}

}  // namespace si::cont
