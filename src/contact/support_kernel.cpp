#include "contact/support_kernel.hpp"

#include <cmath>

#include "contact/anisotropic_half_space.hpp"
#include "contact/layer_compliance.hpp"
#include "contact/reissner_mindlin_compliance.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

constexpr double kMapScale = 2.0;      // L of the map x = L (1 + xi) / (1 - xi)
constexpr int kKappaDegree = 96;       // Chebyshev degree of kappa in xi
constexpr int kTransformDegree = 160;  // and of its cosine transform in y (y_max ~ 24)
// Beyond x = 400 (a wavelength below 1/60 of the stack, several wavelengths within any ply of
// the top ten percent of it) the support is the top layer's half-space to far below 1e-12: kappa
// is then the plate's Poisson term alone (0 for the layers), instead of 400 + transfer steps.
constexpr double kFarField = 400;
// kShell, whose kernel is built for every run (not once per law table): the plies below the top
// one change its face's compliance by ~exp(-2 x t_top / h) of the contrast; ten top plies' worth
// of x (exp(-20) ~ 2e-9) is far enough, 80 for the paper's 8 plies, and 5x cheaper than 400.
constexpr double kShellFarFieldPlies = 10;
// int_0^inf kappa cos(x y) dx is taken over [0, 60] (kappa decays exponentially for the layers
// and like x^-3 for the plate: the tail is below 1e-5 of the integral), then sampled at 200
// points per unit of y for the Hermite interpolation.
constexpr double kTransformRange = 60;
// kShell: below this x the plates' difference is taken linear (kappa_direct).
constexpr double kShellLongWave = 0.2;
constexpr double kTransformSamplesPerUnit = 200;

Vector3d direction(double phi) {
  return Vector3d(std::cos(phi), std::sin(phi), 0);
}

// A layer under the in-plane strain v = e e (Voigt [e11, e22, g12]) with the out-of-plane
// stresses zero (plate bending): its plane-stress stiffness along e and its thickness strain,
// e33 = -nu (the strain along e).
struct PlaneStress {
  double Q = 0;   // v^T Q v, Q = C_pp - C_pt C_tt^-1 C_tp
  double nu = 0;  // [C_tt^-1 C_tp v]_33
};

PlaneStress plane_stress(const Matrix6d& C, double phi) {
  const int p[3] = {0, 1, 5}, t[3] = {2, 3, 4};
  Matrix3d Cpp, Cpt, Ctp, Ctt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Cpp(i, j) = C(p[i], p[j]);
      Cpt(i, j) = C(p[i], t[j]);
      Ctp(i, j) = C(t[i], p[j]);
      Ctt(i, j) = C(t[i], t[j]);
    }
  const Vector3d e = direction(phi);
  const Vector3d v(e[0] * e[0], e[1] * e[1], 2 * e[0] * e[1]);
  const Vector3d out_of_plane = Ctt.inverse() * Ctp * v;  // e_t = -this for e_p = v
  PlaneStress s;
  s.Q = v.dot((Cpp - Cpt * Ctt.inverse() * Ctp) * v);
  s.nu = out_of_plane[0];
  return s;
}

}  // namespace

SupportKernel::SupportKernel(const SupportSpec& spec, double y_max, int directions)
    : spec_(spec), directions_(directions) {
  SI_REQUIRE(spec.support != LocalSupport::kHalfSpace,
             "SupportKernel: a half-space has no thickness correction");
  SI_REQUIRE(!spec.layers.empty(), "SupportKernel: no layers");
  SI_REQUIRE(directions >= 2 && y_max > 0, "SupportKernel: need 2 directions and y_max > 0");
  SI_REQUIRE(spec.indenter_compliance >= 0, "SupportKernel: negative indenter compliance");
  for (const LayerStiffness& l : spec.layers) thickness_ += l.thickness;
  far_field_ =
      spec.support == LocalSupport::kShell
          ? std::min(kFarField, kShellFarFieldPlies * thickness_ / spec.layers.back().thickness)
          : kFarField;
  const Matrix6d& top = spec.layers.back().C;
  for (int j = 0; j < directions_; ++j)
    far_compliance_ += half_space_normal_compliance(top, kPi * j / directions_) / directions_;
  far_compliance_ += spec.indenter_compliance;
  if (spec.support == LocalSupport::kPlate || spec.support == LocalSupport::kShell) {
    SI_REQUIRE(spec.shear_stiffness.llt().info() == Eigen::Success &&
                   spec.shear_stiffness.determinant() > 0,
               "SupportKernel: the plate support needs a positive-definite shear stiffness");
    for (int j = 0; j < directions_; ++j) {
      const double phi = kPi * j / directions_;
      double z = -thickness_ / 2, D = 0, I = 0;
      for (const LayerStiffness& l : spec.layers) {
        const PlaneStress s = plane_stress(l.C, phi);
        const double z1 = z + l.thickness;
        D += s.Q * (z1 * z1 * z1 - z * z * z) / 3;
        const double lo = std::max(z, 0.0), hi = std::max(z1, 0.0);
        I += s.nu * (hi * hi - lo * lo) / 2;
        z = z1;
      }
      const Vector2d e(std::cos(phi), std::sin(phi));
      poisson_c2_.push_back(spec.support == LocalSupport::kShell ? shell_long_wave(phi)
                                                                 : I * thickness_ / D);
      bending_ratio_.push_back(D / (e.dot(spec.shear_stiffness * e) * thickness_ * thickness_));
    }
  }
  // kappa in xi: xi = -1 is x = 0 (kappa = -1: a finite stack's compliance vanishes with k),
  // xi = 1 is x = infinity (kappa = 0).
  const std::vector<double> xi = chebyshev_points(-1, 1, kKappaDegree);
  std::vector<double> values(xi.size());
  for (std::size_t j = 0; j < xi.size(); ++j) {
    if (xi[j] >= 1)
      values[j] = spec.surface == PlateSurface::kMid && spec.support == LocalSupport::kShell
                      ? -1  // the mid-plane's compliance vanishes at short waves
                      : 0;
    else if (xi[j] <= -1)
      values[j] = -1;
    else
      values[j] = kappa_direct(kMapScale * (1 + xi[j]) / (1 - xi[j]));
  }
  kappa_ = ChebyshevSeries(-1, 1, values);
  const KernelQuadrature q = quadrature(kTransformRange, 0.25);
  const std::vector<double> y = chebyshev_points(0, y_max, kTransformDegree);
  std::vector<double> transform(y.size());
  for (std::size_t j = 0; j < y.size(); ++j) {
    double s = 0;
    for (std::size_t i = 0; i < q.x.size(); ++i)
      s += q.weight[i] * q.kappa[i] * std::cos(q.x[i] * y[j]);
    transform[j] = s;
  }
  const ChebyshevSeries series(0, y_max, transform);
  const int samples = static_cast<int>(std::ceil(y_max * kTransformSamplesPerUnit));
  transform_step_ = y_max / samples;
  for (int j = 0; j <= samples; ++j) {
    transform_.push_back(series(j * transform_step_));
    transform_slope_.push_back(series.derivative(j * transform_step_));
  }
}

double SupportKernel::cosine_transform(double y) const {
  const double u = y / transform_step_;
  const int last = static_cast<int>(transform_.size()) - 1;
  SI_REQUIRE(u >= 0 && u <= last + 1e-9, "SupportKernel::cosine_transform: y out of range");
  const int j = std::min(static_cast<int>(u), last - 1);
  const double t = u - j, h = transform_step_;
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  return h00 * transform_[j] + h10 * h * transform_slope_[j] + h01 * transform_[j + 1] +
         h11 * h * transform_slope_[j + 1];
}

double SupportKernel::mean_compliance(double x) const {
  const double k = x / thickness_;
  double sum = 0;
  for (int j = 0; j < directions_; ++j) {
    const double phi = kPi * j / directions_;
    const bool plate =
        spec_.support == LocalSupport::kPlate || spec_.support == LocalSupport::kShell;
    if (plate) sum += poisson_c2_[j] / x / (1 + bending_ratio_[j] * x * x);
    if (spec_.support == LocalSupport::kShell)
      sum -= reissner_mindlin_compliance(spec_.bending_stiffness, spec_.shear_stiffness, phi, k);
    const bool mid = spec_.support == LocalSupport::kShell && spec_.surface == PlateSurface::kMid;
    if (x > far_field_) {
      // The mid-plane's compliance is exp(-x/2) small there; the top face's is the half-space's.
      if (!mid) sum += half_space_normal_compliance(spec_.layers.back().C, phi);
    } else if (mid) {
      sum += plate_face_compliance(spec_.layers, phi, k).mid;
    } else if (spec_.support == LocalSupport::kShell) {
      sum += plate_top_compliance(spec_.layers, phi, k);
    } else if (plate) {
      const PlateFaceCompliance f = plate_face_compliance(spec_.layers, phi, k);
      sum += f.top - f.mid;
    } else {
      const LayerBase base = spec_.support == LocalSupport::kBondedBase ? LayerBase::kBonded
                                                                        : LayerBase::kFrictionless;
      sum += layer_normal_compliance(spec_.layers, base, phi, k);
    }
  }
  return sum / directions_ + spec_.indenter_compliance;
}

// The plates' long-wave difference, H_top - H_RM = -L / x + O(x): the top face's Poisson rise
// relative to the thickness average, twice (the face's rise per curvature, and by reciprocity
// the curvature a face load makes: measured 2 x 5.44e-6 against 1.0873e-5 on [0/90]2S), which
// the Reissner-Mindlin plate's deflection (VAM's thickness average) does not hold. At x = 1e-3
// the O(x^2) rest is ~1e-6 of it and the difference keeps ~9 digits.
double SupportKernel::shell_long_wave(double phi) const {
  const double x = 1e-3, k = x / thickness_;
  const double face = spec_.surface == PlateSurface::kMid
                          ? plate_face_compliance(spec_.layers, phi, k).mid
                          : plate_top_compliance(spec_.layers, phi, k);
  return -x * (face -
               reissner_mindlin_compliance(spec_.bending_stiffness, spec_.shear_stiffness, phi, k));
}

double SupportKernel::kappa_direct(double x) const {
  SI_REQUIRE(x > 0, "SupportKernel::kappa_direct: x must be positive");
  // kShell at long waves: the two plates' compliances (~1 / x^3) swamp their O(x) difference in
  // round-off (kappa off by 0.03 at x = 0.02 and by 1e2 at 1e-4 on the paper's [0]8, against
  // ~3e-5 at 0.2), and that difference is below 0.2 % of H_inf: linear from kappa(0) = -1.
  if (spec_.support == LocalSupport::kShell && x < kShellLongWave)
    return -1 + (mean_compliance(kShellLongWave) / far_compliance_) * x / kShellLongWave;
  return mean_compliance(x) / far_compliance_ - 1;
}

double SupportKernel::kappa(double x) const {
  SI_REQUIRE(x >= 0, "SupportKernel::kappa: x must not be negative");
  return kappa_((x - kMapScale) / (x + kMapScale));
}

KernelQuadrature SupportKernel::quadrature(double x_max, double panel) const {
  const GaussRule g = gauss_legendre(8);
  KernelQuadrature q;
  const int panels = static_cast<int>(std::ceil(x_max / panel));
  const double h = x_max / panels;
  for (int p = 0; p < panels; ++p)
    for (std::size_t i = 0; i < g.points.size(); ++i) {
      const double x = h * (p + (g.points[i] + 1) / 2);
      q.x.push_back(x);
      q.weight.push_back(h / 2 * g.weights[i]);
      q.kappa.push_back(kappa(x));
    }
  return q;
}

}  // namespace si
