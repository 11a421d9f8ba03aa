#include "contact/sphere_on_layer.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

// Gauss-Legendre on [0, b].
void gauss_on(double b, int n, Eigen::VectorXd& t, Eigen::VectorXd& w) {
  const GaussRule g = gauss_legendre(n);
  t.resize(n), w.resize(n);
  for (int i = 0; i < n; ++i) {
    t[i] = b * (g.points[i] + 1) / 2;
    w[i] = b / 2 * g.weights[i];
  }
}

}  // namespace

SphereOnLayer::SphereOnLayer(const SupportKernel& kernel, int nodes)
    : kernel_(kernel), nodes_(nodes) {
  SI_REQUIRE(nodes >= 4, "SphereOnLayer: at least 4 nodes");
}

double SphereOnLayer::kernel(double t, double s) const {
  return (kernel_.cosine_transform(std::abs(t - s)) + kernel_.cosine_transform(t + s)) / kPi;
}

Vector2d SphereOnLayer::applied_kernel(const SphereOnLayerSolution& s, double u) const {
  Vector2d sum = Vector2d::Zero();
  for (Eigen::Index q = 0; q < s.t.size(); ++q) {
    const double kw = kernel(u, s.t[q]) * s.w[q];
    sum += kw * Vector2d(s.g1[q], s.g2[q]);
  }
  return sum;
}

SphereOnLayerSolution SphereOnLayer::solve(double a) const {
  SI_REQUIRE(a >= 0, "SphereOnLayer::solve: negative contact radius");
  SphereOnLayerSolution s;
  s.radius = a;
  if (a == 0) {  // Hertz
    s.approach = 1, s.force = 4.0 / 3.0, s.punch = 2;
    return s;
  }
  gauss_on(a, nodes_, s.t, s.w);
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(nodes_, nodes_);
  for (int p = 0; p < nodes_; ++p)
    for (int q = 0; q < nodes_; ++q) A(p, q) += kernel(s.t[p], s.t[q]) * s.w[q];
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  s.g1 = lu.solve(Eigen::VectorXd::Constant(nodes_, 1 / kPi));
  s.g2 = lu.solve(s.t.cwiseAbs2() / kPi);
  const Vector2d Kg = applied_kernel(s, a);  // g(a) by Nystrom's interpolation
  const double g1a = 1 / kPi - Kg[0], g2a = a * a / kPi - Kg[1];
  if (!(g1a > 0))
    throw_numerical("the sphere-on-layer contact equation has no smooth solution at a / h = " +
                    std::to_string(a));
  const double alpha = g2a / g1a;
  s.approach = alpha / (a * a);
  s.force = 2 * kPi * s.w.dot(alpha * s.g1 - s.g2) / (a * a * a);
  s.punch = 2 * kPi * s.w.dot(s.g1) / a;
  return s;
}

SphereOnLayer::OuterFace SphereOnLayer::outer_face(const SphereOnLayerSolution& s,
                                                   const std::vector<double>& a_over_r) const {
  OuterFace out;
  out.sphere.assign(a_over_r.size(), 0.0);
  out.punch.assign(a_over_r.size(), 0.0);
  const double a = s.radius;
  const double alpha = s.approach * a * a;
  Eigen::VectorXd theta, theta_w;
  for (std::size_t i = 0; i < a_over_r.size(); ++i) {
    const double v = std::min(a_over_r[i], 1.0);
    if (v <= 0) continue;
    const double r = a / v, beta = std::asin(v);
    if (a > 0 && r > kDentRange) continue;
    // The right-hand sides' part, in closed form: 2 int_0^beta f(r sin theta) dtheta with
    // f = 1/pi (punch) and (alpha - t^2)/pi (sphere).
    const double punch = 2 * beta / kPi;
    const double moment = 2 * r * r / kPi * (beta / 2 - std::sin(2 * beta) / 4);
    double c1 = 0, c2 = 0;  // the support's part: 2 int_beta^pi/2 (K g)(r sin theta) dtheta
    if (a > 0) {
      gauss_on(kPi / 2 - beta, 24, theta, theta_w);
      for (Eigen::Index q = 0; q < theta.size(); ++q) {
        const Vector2d Kg = applied_kernel(s, r * std::sin(beta + theta[q]));
        c1 += theta_w[q] * Kg[0];
        c2 += theta_w[q] * Kg[1];
      }
    }
    out.punch[i] = punch + 2 * c1;
    out.sphere[i] = a > 0 ? (alpha * punch - moment + 2 * (alpha * c1 - c2)) / (a * a)
                          : ((2 - 1 / (v * v)) * beta + std::sqrt(1 / (v * v) - 1)) / kPi;
  }
  return out;
}

}  // namespace si
