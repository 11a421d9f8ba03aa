#include "contact/face_influence.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace si {

namespace {

// What the transform takes: kappa for the top face, 1 + kappa for the mid-plane (no 1/r term).
double transformed_shift(const SupportKernel& kernel) {
  return kernel.spec().surface == PlateSurface::kMid ? 1.0 : 0.0;
}

}  // namespace

KappaTail shell_kappa_tail(const SupportKernel& kernel) {
  // H_RM -> 1 / (k e.G.e) at short waves (reissner_mindlin_compliance.hpp), averaged as the
  // kernel averages: kappa -> -(h / x) <1 / e.G.e> / H_inf.
  const Matrix2d& shear_stiffness = kernel.spec().shear_stiffness;
  const int directions = kernel.directions();
  double mean = 0;
  for (int j = 0; j < directions; ++j) {
    const double phi = kPi * j / directions;
    const Vector2d e(std::cos(phi), std::sin(phi));
    mean += 1 / e.dot(shear_stiffness * e) / directions;
  }
  KappaTail t;
  t.t1 = -kernel.thickness() * mean / kernel.far_compliance();
  const double x = 2000;
  t.t3 = x * x * x * (kernel.kappa_direct(x) + transformed_shift(kernel) - t.t1 / x);
  return t;
}

namespace {

HankelJ0 kappa_transform(const SupportKernel& kernel, const KappaTail& tail, double rho_max) {
  const double shift = transformed_shift(kernel);
  return HankelJ0([&kernel, shift](double x) { return kernel.kappa(x) + shift; }, tail.t1, tail.t3,
                  rho_max);
}

}  // namespace

FaceInfluence::FaceInfluence(std::shared_ptr<const SupportKernel> kernel, double r_max)
    : kernel_(std::move(kernel)),
      h_(kernel_->thickness()),
      far_(kernel_->far_compliance()),
      transform_(kappa_transform(*kernel_, shell_kappa_tail(*kernel_), r_max / h_)) {
  SI_REQUIRE(kernel_->spec().support == LocalSupport::kShell,
             "FaceInfluence: the kernel must be of the shell support");
  if (kernel_->spec().surface == PlateSurface::kMid) boussinesq_ = 0;
}

double FaceInfluence::point(double r) const {
  return far_ / (2 * kPi) * (boussinesq_ / r + transform_(r / h_) / h_);
}

double FaceInfluence::disc(double b) const {
  SI_REQUIRE(b > 0, "FaceInfluence::disc: the radius must be positive");
  return far_ / (kPi * b * b) * (boussinesq_ * b + h_ * transform_.moment(b / h_));
}

}  // namespace si
