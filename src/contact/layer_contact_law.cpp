#include "contact/layer_contact_law.hpp"

#include <cmath>

#include "contact/sphere_on_layer.hpp"
#include "core/error.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

// Chebyshev degrees in tau = (lambda / lambda_max)^0.5 and in sigma. The map tau resolves small
// contact radii, where the plate's kernel (its x^-3 tail) puts lambda^3 log lambda terms into
// the solution: in tau they are tau^6 log tau, smooth enough for 1e-7 at degree 32.
constexpr int kRadiusDegree = 32;
constexpr int kProfileDegree = 32;

}  // namespace

LayerContactLaw::LayerContactLaw(const SupportSpec& spec, double sphere_radius,
                                 double max_radius_over_h)
    : R_(sphere_radius), lambda_max_(max_radius_over_h) {
  SI_REQUIRE(sphere_radius > 0 && max_radius_over_h > 0,
             "LayerContactLaw: the radius and the table's range must be positive");
  const SupportKernel kernel(spec, SphereOnLayer::kDentRange + 2 * max_radius_over_h);
  h_ = kernel.thickness();
  modulus_ = 2 / kernel.far_compliance();
  const SphereOnLayer contact(kernel);
  const std::vector<double> tau = chebyshev_points(0, 1, kRadiusDegree);
  const std::vector<double> sigma = chebyshev_points(0, 1, kProfileDegree);
  std::vector<double> a_over_r(sigma.size());
  for (std::size_t j = 0; j < sigma.size(); ++j) a_over_r[j] = 1 - sigma[j] * sigma[j];
  std::vector<double> A(tau.size()), B(tau.size()), P(tau.size());
  Eigen::MatrixXd V(tau.size(), sigma.size());
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const SphereOnLayerSolution s = contact.solve(lambda_max_ * tau[i] * tau[i]);
    A[i] = s.approach, B[i] = s.force, P[i] = s.punch;
    const SphereOnLayer::OuterFace face = contact.outer_face(s, a_over_r);
    for (std::size_t j = 0; j < sigma.size(); ++j) {
      const double s2 = sigma[j] * sigma[j];
      V(i, j) = s2 > 0 ? (face.sphere[j] - (s.approach - 0.5)) / s2 : -1.0;  // the header
    }
  }
  approach_ = ChebyshevSeries(0, 1, A);
  force_ = ChebyshevSeries(0, 1, B);
  punch_ = ChebyshevSeries(0, 1, P);
  outer_ = ChebyshevTable2(0, 1, 0, 1, V);
}

double LayerContactLaw::tau(double lambda) const {
  return std::sqrt(lambda / lambda_max_);
}

// d/dlambda of a series in tau: d tau / d lambda = 1 / (2 tau lambda_max); at lambda = 0 the
// series' slope in tau vanishes (they are even in tau to the orders that matter) and the
// derivative is taken one roundoff step away.
double LayerContactLaw::slope(const ChebyshevSeries& f, double lambda) const {
  const double t = std::max(tau(lambda), 1e-8);
  return f.derivative(t) / (2 * t * lambda_max_);
}

double LayerContactLaw::approach_ratio(double lambda) const {
  return approach_(tau(lambda));
}
double LayerContactLaw::force_ratio(double lambda) const {
  return force_(tau(lambda));
}
double LayerContactLaw::punch_ratio(double lambda) const {
  return punch_(tau(lambda));
}

double LayerContactLaw::lambda_of_alpha(double alpha) const {
  // Solve A(lambda) lambda^2 = alpha R / h^2 for lambda in [0, lambda_max]: increasing in lambda.
  const double target = alpha * R_ / (h_ * h_);
  if (target == 0) return 0;
  const auto f = [&](double l) { return approach_ratio(l) * l * l - target; };
  if (f(lambda_max_) < -1e-12 * target)
    throw_numerical("the local approach " + std::to_string(alpha) +
                    " mm needs a contact radius beyond the finite-thickness law's table (a / h > " +
                    std::to_string(lambda_max_) + ")");
  double lo = 0, hi = lambda_max_;
  double l = std::min(std::sqrt(target), lambda_max_);  // Hertz's start
  for (int it = 0; it < 100; ++it) {
    const double v = f(l);
    if (v > 0)
      hi = l;
    else
      lo = l;
    if (v == 0) return l;
    const double d = slope(approach_, l) * l * l + 2 * l * approach_ratio(l);
    double next = d > 0 ? l - v / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - l) <= 1e-15 * std::max(1.0, l)) return next;
    l = next;
  }
  return l;
}

double LayerContactLaw::contact_radius(double alpha) const {
  return lambda_of_alpha(std::abs(alpha)) * h_;
}

double LayerContactLaw::force(double alpha) const {
  const double a = contact_radius(alpha);
  return std::copysign(force_ratio(a / h_) * modulus_ * a * a * a / R_, alpha);
}

double LayerContactLaw::stiffness(double alpha) const {
  const double l = lambda_of_alpha(std::abs(alpha));
  // dF/dalpha = M h l (3 B + l B') / (2 A + l A'), the factor l of both derivatives cancelled.
  return modulus_ * h_ * l * (3 * force_ratio(l) + l * slope(force_, l)) /
         (2 * approach_ratio(l) + l * slope(approach_, l));
}

double LayerContactLaw::energy(double alpha) const {
  const double l_end = lambda_of_alpha(std::abs(alpha));
  const GaussRule g = gauss_legendre(16);
  double e = 0;
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    const double l = l_end * (g.points[i] + 1) / 2;
    const double F = force_ratio(l) * modulus_ * std::pow(l * h_, 3) / R_;
    const double dalpha = h_ * h_ / R_ * (2 * l * approach_ratio(l) + l * l * slope(approach_, l));
    e += l_end / 2 * g.weights[i] * F * dalpha;
  }
  return e;
}

double LayerContactLaw::approach(double force) const {
  // Invert F(alpha) (increasing) by bisection on alpha's bracket, then Newton.
  const double target = std::abs(force);
  double lo = 0, hi = approach_ratio(lambda_max_) * std::pow(lambda_max_ * h_, 2) / R_;
  SI_REQUIRE(target <= this->force(hi), "LayerContactLaw::approach: force beyond the table");
  double alpha = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const double v = this->force(alpha) - target;
    if (v > 0)
      hi = alpha;
    else
      lo = alpha;
    const double d = stiffness(alpha);
    double next = d > 0 ? alpha - v / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - alpha) <= 1e-15 * std::max(1e-12, alpha)) {
      alpha = next;
      break;
    }
    alpha = next;
  }
  return std::copysign(alpha, force);
}

DentValue LayerContactLaw::dent(double r, double alpha) const {
  return dent_at(alpha).at(r);
}

LayerContactLaw::Dent LayerContactLaw::dent_at(double alpha) const {
  Dent d;
  d.depth_ = std::abs(alpha);
  d.sign_ = alpha < 0 ? -1.0 : 1.0;
  d.R_ = R_;
  d.a_ = contact_radius(d.depth_);
  if (d.a_ > 0) {
    const double l = d.a_ / h_, t = tau(l);
    d.A_ = approach_ratio(l);
    d.A_a_ = slope(approach_, l) / h_;
    d.V_ = outer_.slice(t);
    d.V_a_ = outer_.slice_derivative_x(t, 1 / (2 * std::max(t, 1e-8) * lambda_max_ * h_));
  }
  return d;
}

// u = (a^2/R) [A - 1/2 + s2 V(tau, sigma)], s2 = sigma^2 = 1 - a/r; the rate du/dalpha at fixed r
// is (du/da) / (dalpha/da) of the same tables (the header).
DentValue LayerContactLaw::Dent::at(double r) const {
  SI_REQUIRE(r >= 0, "LayerContactLaw::dent: r must not be negative");
  DentValue d;
  if (r <= a_) {
    d.u = depth_ - r * r / (2 * R_);
    d.rate = 1;
  } else if (a_ > 0) {
    const double s2 = 1 - a_ / r, sigma = std::sqrt(s2);
    const double V = V_(sigma), V_a = V_a_(sigma), sigma_V_sigma = sigma * V_.derivative(sigma);
    d.u = a_ * a_ / R_ * (A_ - 0.5 + s2 * V);
    const double du_da = 2 * a_ / R_ * (A_ - 0.5 + s2 * V) +
                         a_ * a_ / R_ * (A_a_ + s2 * V_a - V / r - sigma_V_sigma / (2 * r));
    const double dalpha_da = (2 * a_ * A_ + a_ * a_ * A_a_) / R_;
    d.rate = du_da / dalpha_da;
  }
  d.u *= sign_;
  return d;
}

}  // namespace si
