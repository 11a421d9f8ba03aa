#include "contact/hankel_j0.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

constexpr int kRemainderDegree = 96;  // Chebyshev degree of the remainder's transform in rho
constexpr double kPanel = 0.25;       // Gauss panel in x (8 points: a few per period of J0)
constexpr int kPanelPoints = 8;
constexpr int kAnglePoints = 64;         // Gauss points of Bessel's integral over [0, pi/2]
constexpr double kSamplesPerUnit = 256;  // Hermite samples per unit of rho
constexpr double kDirectSamples = 4;     // below this many samples, F in closed form

// The tails' transforms and their slopes at rho, z = rho / 2 (header), from one set of Bessel
// functions (std's are ~1 us each and the table samples thousands of rho).
struct Tails {
  double t1 = 0, t1_slope = 0, t3 = 0, t3_slope = 0;
};
Tails tails(double rho) {
  const double z = rho / 2;
  const double i0 = std::cyl_bessel_i(0.0, z), i1 = std::cyl_bessel_i(1.0, z);
  const double k0 = std::cyl_bessel_k(0.0, z), k1 = std::cyl_bessel_k(1.0, z);
  Tails t;
  t.t1 = i0 * k0;
  t.t1_slope = 0.5 * (i1 * k0 - i0 * k1);
  t.t3 = z * (i0 * k1 - i1 * k0);
  // d/dz of z (I0 K1 - I1 K0) is 2 z (I1 K1 - I0 K0) (I0' = I1, K0' = -K1, I1' = I0 - I1/z,
  // K1' = -K0 - K1/z); d/drho is half of it.
  t.t3_slope = z * (i1 * k1 - i0 * k0);
  return t;
}

}  // namespace

HankelJ0::HankelJ0(const std::function<double(double)>& f, double t1, double t3, double rho_max,
                   double x_max)
    : t1_(t1), s3_(t3 + t1 / 2), rho_max_(rho_max), moment_rule_(gauss_legendre(24)) {
  SI_REQUIRE(rho_max > 0 && x_max > 0, "HankelJ0: rho_max and x_max must be positive");
  const GaussRule g = gauss_legendre(kPanelPoints);
  const int panels = static_cast<int>(std::ceil(x_max / kPanel));
  const double width = x_max / panels;
  std::vector<double> x, wr;  // nodes and weight times the remainder there
  for (int p = 0; p < panels; ++p)
    for (int i = 0; i < kPanelPoints; ++i) {
      const double xi = width * (p + (g.points[i] + 1) / 2);
      const double q = 1 + xi * xi;
      const double remainder = f(xi) - t1 / std::sqrt(q) - s3_ / (q * std::sqrt(q));
      x.push_back(xi);
      wr.push_back(width / 2 * g.weights[i] * remainder);
    }
  // J0(x rho) = (2/pi) int_0^{pi/2} cos(x rho sin t) dt (Bessel's integral): the remainder's
  // cosine transform C(y) = int r(x) cos(x y) dx as a series in y, then F(rho) = (2/pi)
  // int_0^{pi/2} C(rho sin t) dt by Gauss; cosines and Clenshaw sums instead of ~1e5 Bessel
  // functions (std's J0 is ~4 us each: 0.25 s of set-up before).
  const std::vector<double> nodes = chebyshev_points(0, rho_max, kRemainderDegree);
  std::vector<double> values(nodes.size());
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    double s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) s += wr[i] * std::cos(x[i] * nodes[j]);
    values[j] = s;
  }
  const ChebyshevSeries cosine(0, rho_max, values);
  const GaussRule angle = gauss_legendre(kAnglePoints);
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    double s = 0;
    for (std::size_t i = 0; i < angle.points.size(); ++i) {
      const double t = kPi / 4 * (angle.points[i] + 1);
      s += angle.weights[i] * cosine(nodes[j] * std::sin(t));
    }
    values[j] = s / 2;  // (2/pi) (pi/4) sum w_i C
  }
  remainder_ = ChebyshevSeries(0, rho_max, values);
  const int samples = static_cast<int>(std::ceil(rho_max * kSamplesPerUnit));
  step_ = rho_max / samples;
  value_.assign(samples + 1, 0.0);
  slope_.assign(samples + 1, 0.0);
  for (int j = 1; j <= samples; ++j) {
    const double rho = j * step_;
    const Tails t = tails(rho);
    value_[j] = t1_ * t.t1 + s3_ * t.t3 + remainder_(rho) + t1_ * std::log(rho);
    slope_[j] = t1_ * t.t1_slope + s3_ * t.t3_slope + remainder_.derivative(rho) + t1_ / rho;
  }
}

double HankelJ0::direct(double rho) const {
  const Tails t = tails(rho);
  return t1_ * t.t1 + s3_ * t.t3 + remainder_(rho);
}

double HankelJ0::operator()(double rho) const {
  SI_REQUIRE(rho > 0 && rho <= rho_max_ * (1 + 1e-12), "HankelJ0: rho out of (0, rho_max]");
  const double u = rho / step_;
  // Within the first samples the rho^2 ln rho terms are not cubics: closed forms.
  if (u < kDirectSamples) return direct(rho);
  const int last = static_cast<int>(value_.size()) - 1;
  const int j = std::min(static_cast<int>(u), last - 1);
  const double t = u - j, h = step_;
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  return h00 * value_[j] + h10 * h * slope_[j] + h01 * value_[j + 1] + h11 * h * slope_[j + 1] -
         t1_ * std::log(rho);
}

// rho = b s^2 takes the logarithm at 0 into s^3 ln s, smooth enough for 24 Gauss points.
double HankelJ0::moment(double b) const {
  SI_REQUIRE(b >= 0 && b <= rho_max_ * (1 + 1e-12), "HankelJ0::moment: b out of [0, rho_max]");
  if (b == 0) return 0;
  const GaussRule& g = moment_rule_;
  double sum = 0;
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    const double s = (g.points[i] + 1) / 2;
    sum += g.weights[i] / 2 * s * s * s * direct(b * s * s);
  }
  return 2 * b * b * sum;
}

}  // namespace si
