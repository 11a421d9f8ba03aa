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

// Second derivative of the branch u'' = (x'', p''), from F_uu[t, t] by a second difference.
bool branch_curvature(Problem& problem, BorderedSolver& bordered, const TangentPoint& tp, double h,
                      Vector& xpp, double& ppp) {
  const Point& pt = tp.point;
  Vector f_plus;
  Vector f_zero;
  Vector f_minus;
  if (!problem.residual(pt.x + h * tp.tangent_x, pt.p + h * pt.tangent_p, f_plus) ||
      !problem.residual(pt.x, pt.p, f_zero) ||
      !problem.residual(pt.x - h * tp.tangent_x, pt.p - h * pt.tangent_p, f_minus))
    return false;
  xpp = -(f_plus - 2.0 * f_zero + f_minus) / (h * h);
  return bordered.solve(tp.tangent_x, pt.tangent_p, xpp, 0.0, ppp);
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
  if (!needs.curvatures) return;
  const Vector m_tt = (monitors_at(problem, pt.x, pt.p, t, tp_p, h2) - 2.0 * pt.monitors +
                       monitors_at(problem, pt.x, pt.p, t, tp_p, -h2)) /
                      (h2 * h2);
  Vector xpp;
  double ppp = 0.0;
  if (!branch_curvature(problem, bordered, tp, h2, xpp, ppp)) {
    pt.monitor_curvatures =
        Vector::Constant(pt.monitors.size(), std::numeric_limits<double>::quiet_NaN());
    return;
  }
  // grad m . u'' by a central difference along the unit vector u'' / |u''|.
  const double size = std::sqrt(bordered.inner(xpp, ppp, xpp, ppp));
  pt.monitor_curvatures = m_tt;
  if (size > 0.0 && std::isfinite(size)) {
    const Vector e_x = xpp / size;
    const double e_p = ppp / size;
    pt.monitor_curvatures += size *
                             (monitors_at(problem, pt.x, pt.p, e_x, e_p, h1) -
                              monitors_at(problem, pt.x, pt.p, e_x, e_p, -h1)) /
                             (2.0 * h1);
  }
}

}  // namespace

bool analyse_point(Problem& problem, BorderedSolver& bordered, const Vector& x, double p,
                   const Vector& ref_x, double ref_p, const AnalysisNeeds& needs,
                   TangentPoint& out) {
  Point& pt = out.point;
  pt.x = x;
  pt.p = p;
  if (!bordered.setup(x, p)) return false;
  pt.jacobian_sign = problem.jacobian_sign();
  const Vector ref = ref_x.size() == x.size() ? ref_x : Vector();
  if (!bordered.tangent(ref, ref_p, out.tangent_x, pt.tangent_p)) return false;
  pt.monitors = problem.monitors(x, p);
  pt.monitor_slopes.resize(0);
  pt.monitor_curvatures.resize(0);
  if (needs.slopes || needs.curvatures) monitor_derivatives(problem, bordered, needs, out);
  pt.signature = needs.signature ? problem.signature(x, p) : std::vector<int>{};
  return true;
}

}  // namespace si::cont
