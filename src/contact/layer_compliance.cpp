#include "contact/layer_compliance.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "core/error.hpp"
#include "core/matrix_exponential.hpp"
#include "material/stiffness_contraction.hpp"

namespace si {
namespace {

using Complex = std::complex<double>;
using Matrix6c = Eigen::Matrix<Complex, 6, 6>;
using Matrix9c = Eigen::Matrix<Complex, 9, 9>;
using Basis = Eigen::Matrix<Complex, 6, 3>;
using Block3c = Eigen::Matrix<Complex, 3, 3>;

// The state matrix of a layer for the direction e, with the traction scaled by 1/c_ref so that
// both halves of the state have the same magnitude.
Matrix6c state_matrix(const Matrix6d& C, const Vector3d& e, double c_ref) {
  const Vector3d n(0, 0, 1);
  const Matrix3d Q = stiffness_contraction(C, e, e), R = stiffness_contraction(C, e, n);
  const Matrix3d T_inv = stiffness_contraction(C, n, n).inverse();
  const Complex i(0, 1);
  Matrix6c A;
  A.topLeftCorner(3, 3) = -i * (T_inv * R.transpose()).cast<Complex>();
  A.topRightCorner(3, 3) = (c_ref * T_inv).cast<Complex>();
  A.bottomLeftCorner(3, 3) = ((Q - R * T_inv * R.transpose()) / c_ref).cast<Complex>();
  A.bottomRightCorner(3, 3) = -i * (R * T_inv).cast<Complex>();
  return A;
}

// An orthonormal basis (6 x 3) of the states that satisfy the bottom's conditions, the basis of
// the mid-plane's states and the integral of U over the thickness (3 x 3), all on the same
// coefficients: a state is basis * c.
struct Sweep {
  Basis basis = Basis::Zero();
  Block3c mid = Block3c::Zero();       // free plate, from the mid-plane on (has_mid)
  Block3c integral = Block3c::Zero();  // free plate: int U dzeta
  bool has_mid = false;
};

// basis = Q R: carry every block to the new coefficients R c.
void orthonormalise(Sweep& s) {
  const Eigen::HouseholderQR<Basis> qr(s.basis);
  const Basis q = qr.householderQ() * Basis::Identity();
  const Block3c r = qr.matrixQR().template topRows<3>().template triangularView<Eigen::Upper>();
  const Block3c r_inv = r.inverse();
  s.basis = q;
  s.mid = (s.mid * r_inv).eval();
  s.integral = (s.integral * r_inv).eval();
}

double reference_modulus(const std::vector<LayerStiffness>& layers) {
  double c = 0;
  for (const LayerStiffness& l : layers) c = std::max(c, l.C(2, 2));
  return c;
}

void check_stack(const std::vector<LayerStiffness>& layers, double wavenumber) {
  SI_REQUIRE(!layers.empty(), "layer compliance: no layers");
  for (const LayerStiffness& l : layers)
    SI_REQUIRE(l.thickness > 0, "layer compliance: a layer thickness is not positive");
  SI_REQUIRE(wavenumber > 0 && std::isfinite(wavenumber),
             "layer compliance: the wavenumber must be positive");
}

// Carries the sweep through `thickness` of one layer (zeta = k thickness) in steps of at most 1.
void propagate(Sweep& s, const Matrix6c& A, double zeta, bool integrate) {
  const int steps = std::max(1, static_cast<int>(std::ceil(zeta)));
  const double d = zeta / steps;
  Matrix6c E;                                                             // exp(A d)
  Eigen::Matrix<Complex, 3, 6> F = Eigen::Matrix<Complex, 3, 6>::Zero();  // int_0^d [I 0] exp(A z)
  if (integrate) {
    Matrix9c B = Matrix9c::Zero();
    B.topLeftCorner<6, 6>() = A * d;
    B.bottomLeftCorner<3, 3>() = Block3c::Identity() * d;
    const Matrix9c eB = matrix_exponential(B);
    E = eB.topLeftCorner<6, 6>();
    F = eB.bottomLeftCorner<3, 6>();
  } else {
    E = matrix_exponential(Matrix6c(A * d));
  }
  for (int k = 0; k < steps; ++k) {
    if (integrate) s.integral += F * s.basis;
    s.basis = (E * s.basis).eval();
    orthonormalise(s);
  }
}

// U = Y s at the top for the rows `U` of a basis-like block: the normal component of Y.
double normal_compliance(const Block3c& U_rows, const Sweep& s, double c_ref) {
  const Block3c Y = U_rows * Block3c(s.basis.bottomRows<3>()).inverse();
  return Y(2, 2).real() / c_ref;
}

}  // namespace

double layer_normal_compliance(const std::vector<LayerStiffness>& layers, LayerBase base,
                               double phi_rad, double wavenumber) {
  check_stack(layers, wavenumber);
  const Vector3d e(std::cos(phi_rad), std::sin(phi_rad), 0);
  const double c_ref = reference_modulus(layers);
  Sweep s;
  if (base == LayerBase::kBonded) {
    s.basis.bottomRows<3>().setIdentity();  // U = 0, any traction
  } else {
    s.basis(0, 0) = s.basis(1, 1) = 1;  // U1, U2 free, U3 = 0
    s.basis(5, 2) = 1;                  // s1 = s2 = 0, s3 free
  }
  for (const LayerStiffness& l : layers)
    propagate(s, state_matrix(l.C, e, c_ref), wavenumber * l.thickness, false);
  return normal_compliance(s.basis.topRows<3>(), s, c_ref);
}

PlateFaceCompliance plate_face_compliance(const std::vector<LayerStiffness>& layers, double phi_rad,
                                          double wavenumber) {
  check_stack(layers, wavenumber);
  const Vector3d e(std::cos(phi_rad), std::sin(phi_rad), 0);
  const double c_ref = reference_modulus(layers);
  double total = 0;
  for (const LayerStiffness& l : layers) total += l.thickness;
  Sweep s;
  s.basis.topRows<3>().setIdentity();  // traction-free bottom face: U free, s = 0
  double z = 0;                        // from the bottom face
  for (const LayerStiffness& l : layers) {
    const Matrix6c A = state_matrix(l.C, e, c_ref);
    const double below_mid = std::clamp(total / 2 - z, 0.0, l.thickness);
    if (below_mid > 0) propagate(s, A, wavenumber * below_mid, true);
    if (!s.has_mid && z + below_mid >= total / 2) {
      s.mid = s.basis.topRows<3>();
      s.has_mid = true;
    }
    if (l.thickness - below_mid > 0) propagate(s, A, wavenumber * (l.thickness - below_mid), true);
    z += l.thickness;
  }
  PlateFaceCompliance out;
  out.top = normal_compliance(s.basis.topRows<3>(), s, c_ref);
  out.mid = normal_compliance(s.mid, s, c_ref);
  out.average = normal_compliance(s.integral / (wavenumber * total), s, c_ref);
  return out;
}

double plate_top_compliance(const std::vector<LayerStiffness>& layers, double phi_rad,
                            double wavenumber) {
  check_stack(layers, wavenumber);
  const Vector3d e(std::cos(phi_rad), std::sin(phi_rad), 0);
  const double c_ref = reference_modulus(layers);
  Sweep s;
  s.basis.topRows<3>().setIdentity();  // traction-free bottom face: U free, s = 0
  for (const LayerStiffness& l : layers)
    propagate(s, state_matrix(l.C, e, c_ref), wavenumber * l.thickness, false);
  return normal_compliance(s.basis.topRows<3>(), s, c_ref);
}

}  // namespace si
