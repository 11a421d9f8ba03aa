#include "continuation/point_analysis.hpp"

#include <cmath>
#include <limits>

namespace si::cont {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

Vector monitors_at(Problem& problem, const Vector& x, double p, const Vector& dx, double dp,
                   double h) {
  return problem.monitors(x + h * dx, p + h * dp);
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

// m'' and p'' with second-difference step h2 (first differences along u'' with h1). false when
// u'' cannot be computed.
bool second_derivatives(Problem& problem, BorderedSolver& bordered, const TangentPoint& tp,
                        const Vector& f_zero, double h1, double h2, Vector& mpp, double& ppp) {
  const Point& pt = tp.point;
  const Vector& t = tp.tangent_x;
  mpp = (monitors_at(problem, pt.x, pt.p, t, pt.tangent_p, h2) - 2.0 * pt.monitors +
         monitors_at(problem, pt.x, pt.p, t, pt.tangent_p, -h2)) /
        (h2 * h2);
  Vector xpp;
  if (!branch_curvature(problem, bordered, tp, f_zero, h2, xpp, ppp)) return false;
  // grad m . u'' by a central difference along the unit vector u'' / |u''|.
  const double size = std::sqrt(bordered.inner(xpp, ppp, xpp, ppp));
  if (size > 0.0 && std::isfinite(size)) {
    const Vector e_x = xpp / size;
    const double e_p = ppp / size;
    mpp += size *
           (monitors_at(problem, pt.x, pt.p, e_x, e_p, h1) -
            monitors_at(problem, pt.x, pt.p, e_x, e_p, -h1)) /
           (2.0 * h1);
  }
  return true;
}

void monitor_derivatives(Problem& problem, BorderedSolver& bordered, const AnalysisNeeds& needs,
                         TangentPoint& tp) {
  Point& pt = tp.point;
  const double scale = 1.0 + std::sqrt(bordered.inner(pt.x, pt.p, pt.x, pt.p));
  const double h1 = std::cbrt(kEps) * scale;
  const double h2 = std::sqrt(std::sqrt(kEps)) * scale;
  const Vector& t = tp.tangent_x;
  const double tp_p = pt.tangent_p;
  pt.monitor_slopes = (monitors_at(problem, pt.x, pt.p, t, tp_p, h1) -
                       monitors_at(problem, pt.x, pt.p, t, tp_p, -h1)) /
                      (2.0 * h1);
  if (!(needs.curvatures || needs.curvature_errors)) return;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Vector f_zero;
  double ppp = 0.0;
  if (!problem.residual(pt.x, pt.p, f_zero) ||
      !second_derivatives(problem, bordered, tp, f_zero, h1, h2, pt.monitor_curvatures, ppp)) {
    pt.monitor_curvatures = Vector::Constant(pt.monitors.size(), nan);
    return;
  }
  if (!needs.curvature_errors) return;
  Vector mpp_coarse;
  double ppp_coarse = 0.0;
  pt.parameter_curvature = ppp;
  if (!second_derivatives(problem, bordered, tp, f_zero, h1, 2.0 * h2, mpp_coarse, ppp_coarse)) {
    pt.monitor_curvature_errors = Vector::Constant(pt.monitors.size(), nan);
    pt.parameter_curvature_error = nan;
    return;
  }
  const Vector roundoff = 4.0 * kEps * pt.monitors.cwiseAbs() / (h2 * h2);
  pt.monitor_curvature_errors = (pt.monitor_curvatures - mpp_coarse).cwiseAbs().cwiseMax(roundoff);
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
