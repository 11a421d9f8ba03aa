#include "shell/quad4_shell.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "shell/eas_membrane.hpp"
#include "shell/mitc4_tying.hpp"

namespace si {
namespace {

// Generalised strains in the order [e11, 2e12, e22, k11, 2k12, k22, g1, g2] (covariant or local).
using Vector8d = Eigen::Matrix<double, 8, 1>;
using Matrix8d = Eigen::Matrix<double, 8, 8>;
using Matrix8x20d = Eigen::Matrix<double, 8, kShellElementDofs>;
using Matrix3x2d = Eigen::Matrix<double, 3, 2>;
using RotationBases = std::array<Matrix3x2d, 4>;  // delta d_I = T_I (a_I, b_I), T_I = [-v2, v1]

// Short numbers for error messages.
std::string number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

// Mid-surface quantities at one parametric point (a = xi, eta).
struct PointKinematics {
  Shape4 shape;
  std::array<Vector3d, 2> X_a, x_a, D_a, d_a;
  Vector3d D, d;
};

PointKinematics point_kinematics(ShapeSet set, const ElementGeometry& g,
                                 const std::array<NodeState, 4>& nodes, double xi, double eta) {
  PointKinematics p;
  p.shape = evaluate_shape4(set, xi, eta);
  p.D = p.d = Vector3d::Zero();
  for (int a = 0; a < 2; ++a) p.X_a[a] = p.x_a[a] = p.D_a[a] = p.d_a[a] = Vector3d::Zero();
  for (int i = 0; i < 4; ++i) {
    const double dN[2] = {p.shape.N_xi(i), p.shape.N_eta(i)};
    const Vector3d x = g.X[i] + nodes[i].u;
    p.D += p.shape.N(i) * g.D[i];
    p.d += p.shape.N(i) * nodes[i].d;
    for (int a = 0; a < 2; ++a) {
      p.X_a[a] += dN[a] * g.X[i];
      p.x_a[a] += dN[a] * x;
      p.D_a[a] += dN[a] * g.D[i];
      p.d_a[a] += dN[a] * nodes[i].d;
    }
  }
  return p;
}

// Covariant strains of the first-order kinematics (Simo & Fox 1989, Part I: membrane, bending
// and transverse shear measures of the stress-resultant shell; quad4_shell.hpp).
Vector8d covariant_strains(const PointKinematics& p) {
  const auto& x = p.x_a;
  const auto& X = p.X_a;
  Vector8d e;
  e << (x[0].dot(x[0]) - X[0].dot(X[0])) / 2, x[0].dot(x[1]) - X[0].dot(X[1]),
      (x[1].dot(x[1]) - X[1].dot(X[1])) / 2, x[0].dot(p.d_a[0]) - X[0].dot(p.D_a[0]),
      x[0].dot(p.d_a[1]) + x[1].dot(p.d_a[0]) - X[0].dot(p.D_a[1]) - X[1].dot(p.D_a[0]),
      x[1].dot(p.d_a[1]) - X[1].dot(p.D_a[1]), x[0].dot(p.d) - X[0].dot(p.D),
      x[1].dot(p.d) - X[1].dot(p.D);
  return e;
}

// First variation of covariant_strains with respect to q (rows as above).
Matrix8x20d covariant_strain_derivative(const PointKinematics& p, const RotationBases& T) {
  const auto& x = p.x_a;
  const auto& dd = p.d_a;
  Matrix8x20d B = Matrix8x20d::Zero();
  for (int i = 0; i < 4; ++i) {
    const double N = p.shape.N(i), N1 = p.shape.N_xi(i), N2 = p.shape.N_eta(i);
    const int u = kShellNodeDofs * i, r = u + 3;
    B.block<1, 3>(0, u) = N1 * x[0].transpose();
    B.block<1, 3>(1, u) = (N2 * x[0] + N1 * x[1]).transpose();
    B.block<1, 3>(2, u) = N2 * x[1].transpose();
    B.block<1, 3>(3, u) = N1 * dd[0].transpose();
    B.block<1, 3>(4, u) = (N1 * dd[1] + N2 * dd[0]).transpose();
    B.block<1, 3>(5, u) = N2 * dd[1].transpose();
    B.block<1, 3>(6, u) = N1 * p.d.transpose();
    B.block<1, 3>(7, u) = N2 * p.d.transpose();
    B.block<1, 2>(3, r) = N1 * x[0].transpose() * T[i];
    B.block<1, 2>(4, r) = (N2 * x[0] + N1 * x[1]).transpose() * T[i];
    B.block<1, 2>(5, r) = N2 * x[1].transpose() * T[i];
    B.block<1, 2>(6, r) = N * x[0].transpose() * T[i];
    B.block<1, 2>(7, r) = N * x[1].transpose() * T[i];
  }
  return B;
}

// The geometric stiffness sum_c s_c d2(e_c)/dq2 of the covariant strains, s_c covariant stress
// weights, summed over points. Every second derivative is a product of shape-function values
// and nodal bases, so the points' contributions are summed as 4x4 nodal coefficients (and one
// vector per node for the director's second variation) and spread over the 20x20 matrix once.
class GeometricStiffness {
 public:
  void add(const PointKinematics& p, const Vector8d& s) {
    const Eigen::Vector4d &N = p.shape.N, &N1 = p.shape.N_xi, &N2 = p.shape.N_eta;
    const Eigen::Matrix4d mixed = N1 * N2.transpose() + N2 * N1.transpose();
    uu_.noalias() += s(0) * N1 * N1.transpose() + s(1) * mixed + s(2) * N2 * N2.transpose();
    ur_.noalias() += s(3) * N1 * N1.transpose() + s(4) * mixed + s(5) * N2 * N2.transpose() +
                     (s(6) * N1 + s(7) * N2) * N.transpose();
    // Second variation of the director: delta2 d_i = -(theta . theta') d_i, weighted by the
    // strains' derivative with respect to d_i.
    const Vector3d w1 = s(3) * p.x_a[0] + s(4) * p.x_a[1];
    const Vector3d w2 = s(4) * p.x_a[0] + s(5) * p.x_a[1];
    const Vector3d w0 = s(6) * p.x_a[0] + s(7) * p.x_a[1];
    director_.noalias() += w1 * N1.transpose() + w2 * N2.transpose() + w0 * N.transpose();
  }

  // K += the accumulated terms (u-u, u-rotation and its transpose, rotation-rotation).
  void add_to(const std::array<NodeState, 4>& nodes, const RotationBases& T, Matrix20d& K) const {
    for (int i = 0; i < 4; ++i) {
      const int ui = kShellNodeDofs * i;
      for (int j = 0; j < 4; ++j) {
        const int uj = kShellNodeDofs * j;
        K.block<3, 3>(ui, uj).diagonal().array() += uu_(i, j);
        K.block<3, 2>(ui, uj + 3) += ur_(i, j) * T[j];
        K.block<2, 3>(uj + 3, ui) += ur_(i, j) * T[j].transpose();
      }
      K.block<2, 2>(ui + 3, ui + 3).diagonal().array() -= director_.col(i).dot(nodes[i].d);
    }
  }

 private:
  Eigen::Matrix4d uu_ = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d ur_ = Eigen::Matrix4d::Zero();
  Eigen::Matrix<double, 3, 4> director_ = Eigen::Matrix<double, 3, 4>::Zero();
};

// Local frame (t1, t2, n) at p and the map from covariant to local strains (block diagonal,
// e_local = L e_cov); area = |X,xi x X,eta|.
struct LocalFrame {
  Matrix8d L;
  double area;
};

LocalFrame local_frame(const PointKinematics& p, const Vector3d& material_axis) {
  const Vector3d normal = p.X_a[0].cross(p.X_a[1]);
  LocalFrame f;
  f.area = normal.norm();
  const double scale = p.X_a[0].squaredNorm() + p.X_a[1].squaredNorm();
  if (!(f.area > 1e-10 * scale))
    throw_input("degenerate shell element: zero-area mid-surface (|X,xi x X,eta| = " +
                    number(f.area) + " at a Gauss point)",
                Where{"", "element", "", 0});
  Vector3d n = normal / f.area;
  const double cos_dn = p.D.dot(n) / p.D.norm();
  if (!(std::abs(cos_dn) > 0.1))
    throw_input("degenerate shell element: director nearly tangent to the mid-surface (cos = " +
                    number(cos_dn) + " between director and normal; |cos| must exceed 0.1)",
                Where{"", "element", "", 0});
  if (cos_dn < 0) n = -n;
  Vector3d t1 = material_axis - material_axis.dot(n) * n;
  t1 = t1.norm() > 1e-8 * material_axis.norm() ? t1.normalized() : p.X_a[0].normalized();
  const Vector3d t2 = n.cross(t1);
  Matrix2d J;  // J(a, i) = X,a . t_i
  J << p.X_a[0].dot(t1), p.X_a[0].dot(t2), p.X_a[1].dot(t1), p.X_a[1].dot(t2);
  const Matrix2d C = J.inverse();  // C(i, a) = G^a . t_i
  Eigen::Matrix3d M;               // [e11, 2e12, e22] local from covariant
  M << C(0, 0) * C(0, 0), C(0, 0) * C(0, 1), C(0, 1) * C(0, 1),                             //
      2 * C(0, 0) * C(1, 0), C(0, 0) * C(1, 1) + C(0, 1) * C(1, 0), 2 * C(0, 1) * C(1, 1),  //
      C(1, 0) * C(1, 0), C(1, 0) * C(1, 1), C(1, 1) * C(1, 1);
  f.L.setZero();
  f.L.block<3, 3>(0, 0) = M;
  f.L.block<3, 3>(3, 3) = M;
  f.L.block<2, 2>(6, 6) = C;
  return f;
}

// B_local = L B_cov using L's block-diagonal structure (membrane, bending: M; shear: C): a
// tenth of the work of the dense 8x8 product, which Eigen would also route through its general
// (packing) matrix kernel at these sizes.
void to_local(const LocalFrame& f, const Matrix8x20d& B, Matrix8x20d& out) {
  const auto M = f.L.topLeftCorner<3, 3>();
  out.topRows<3>().noalias() = M.lazyProduct(B.topRows<3>());
  out.middleRows<3>(3).noalias() = M.lazyProduct(B.middleRows<3>(3));
  out.bottomRows<2>().noalias() = f.L.bottomRightCorner<2, 2>().lazyProduct(B.bottomRows<2>());
}

// Strains and their first variation at the tying points of the assumed shear field.
struct TyingData {
  std::array<PointKinematics, 4> point;
  Eigen::Vector4d gamma;
  Eigen::Matrix<double, 4, kShellElementDofs> B;
};

// Everything the element needs per call, with the assumed shear substituted if required.
class Quad4Evaluation {
 public:
  Quad4Evaluation(const Quad4Options& options, const ElementGeometry& g,
                  const std::array<NodeState, 4>& nodes)
      : options_(options), g_(g), nodes_(nodes) {
    for (int i = 0; i < 4; ++i) T_[i] << -nodes[i].v2, nodes[i].v1;
    if (options.membrane == MembraneTreatment::kEas4) {
      // Reference quantities only (X, D): the enhancement does not depend on q.
      const LocalFrame centre =
          local_frame(point_kinematics(options.shape, g, nodes, 0, 0), g.material_axis);
      centre_membrane_map_ = centre.L.topLeftCorner<3, 3>();
      centre_area_ = centre.area;
    }
    if (options.shear != ShearTreatment::kMitc4) return;
    for (int t = 0; t < 4; ++t) {
      const TyingPoint& tp = kMitc4TyingPoints[t];
      tying_.point[t] = point_kinematics(options.shape, g, nodes, tp.xi, tp.eta);
      tying_.gamma(t) = covariant_strains(tying_.point[t])(6 + tp.component);
      tying_.B.row(t) = covariant_strain_derivative(tying_.point[t], T_).row(6 + tp.component);
    }
  }

  // Local strains E, their derivative B (= dE/dq), the covariant-to-local map and the point;
  // G = the local membrane strains per EAS parameter (zero without enhancement).
  struct Point {
    PointKinematics kin;
    LocalFrame frame;
    Vector8d E;
    Matrix8x20d B;
    EasModes G;
  };

  Point at(double xi, double eta) const {
    Point out;
    out.kin = point_kinematics(options_.shape, g_, nodes_, xi, eta);
    out.frame = local_frame(out.kin, g_.material_axis);
    Vector8d e = covariant_strains(out.kin);
    Matrix8x20d B = covariant_strain_derivative(out.kin, T_);
    if (options_.shear == ShearTreatment::kMitc4) {
      const Eigen::Matrix<double, 2, 4> w = mitc4_shear_interpolation(xi, eta);
      e.tail<2>() = w * tying_.gamma;
      B.bottomRows<2>().noalias() = w.lazyProduct(tying_.B);
    }
    out.E = out.frame.L * e;
    to_local(out.frame, B, out.B);
    out.G = options_.membrane == MembraneTreatment::kEas4
                ? eas4_membrane_modes(centre_membrane_map_, centre_area_ / out.frame.area, xi, eta)
                : EasModes::Zero();
    return out;
  }

  // Geometric stiffness of covariant stress weights s at a point; with MITC the shear weights
  // are passed to the tying points (accumulated, added by finish_geometric).
  void add_geometric(double xi, double eta, const PointKinematics& kin, Vector8d s) {
    if (options_.shear == ShearTreatment::kMitc4) {
      tying_weight_ += mitc4_shear_interpolation(xi, eta).transpose() * s.tail<2>();
      s.tail<2>().setZero();
    }
    geometric_.add(kin, s);
  }

  void finish_geometric(Matrix20d& K) {
    if (options_.shear == ShearTreatment::kMitc4)
      for (int t = 0; t < 4; ++t) {
        Vector8d s = Vector8d::Zero();
        s(6 + kMitc4TyingPoints[t].component) = tying_weight_(t);
        geometric_.add(tying_.point[t], s);
      }
    geometric_.add_to(nodes_, T_, K);
  }

 private:
  const Quad4Options& options_;
  const ElementGeometry& g_;
  const std::array<NodeState, 4>& nodes_;
  RotationBases T_;
  TyingData tying_;
  Eigen::Vector4d tying_weight_ = Eigen::Vector4d::Zero();
  GeometricStiffness geometric_;
  Eigen::Matrix3d centre_membrane_map_ = Eigen::Matrix3d::Zero();  // M0 (eas_membrane.hpp)
  double centre_area_ = 0;                                         // det J0
};

struct GaussRule {
  int n;
  double x[4];
  double w[4];
};

GaussRule gauss_rule(int n) {
  if (n == 2) return {2, {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}, {1, 1}};
  SI_REQUIRE(n == 4, "shell element: Gauss rule must have 2 or 4 points per direction");
  return {4,
          {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526},
          {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538}};
}

std::array<NodeState, 4> reference_states(const ElementGeometry& g) {
  std::array<NodeState, 4> ref;
  for (int i = 0; i < 4; ++i) ref[i] = reference_node_state(g.D[i]);
  return ref;
}

// Linear-mode dofs: u and the rotation vector taking D to d, on the reference axes V1, V2.
Vector20d linear_dofs(const std::array<NodeState, 4>& ref, const std::array<NodeState, 4>& nodes) {
  Vector20d q;
  for (int i = 0; i < 4; ++i) {
    const Vector3d axis = ref[i].d.cross(nodes[i].d);  // sin(angle) * unit axis
    const double s = axis.norm();
    const double angle = std::atan2(s, ref[i].d.dot(nodes[i].d));
    const Vector3d theta = s > 1e-12 ? Vector3d(axis * (angle / s)) : axis;
    q.segment<3>(kShellNodeDofs * i) = nodes[i].u;
    q.segment<2>(kShellNodeDofs * i + 3) << theta.dot(ref[i].v1), theta.dot(ref[i].v2);
  }
  return q;
}

Matrix8d law_matrix(const ShellLaw& law) {
  Matrix8d C = Matrix8d::Zero();
  C.topLeftCorner<6, 6>() = law.A_R;
  C.bottomRightCorner<2, 2>() = law.G;
  return C;
}

// The material tangent sum_k dA_k B_k^T C B_k. It is symmetric: only its lower triangle is
// computed, as column dot products of the points' stacked rows (dA B and C B, four points, 32
// rows, at a time), and mirrored; the mirror makes it exactly symmetric.
class MaterialTangent {
 public:
  explicit MaterialTangent(const Matrix8d& C) : C_(C) {}

  void add(const Matrix8x20d& B, double dA) {
    B_.middleRows<8>(8 * points_) = dA * B;
    CB_.middleRows<8>(8 * points_).noalias() = C_.lazyProduct(B);
    if (++points_ == kBatch) flush();
  }

  void add_to(Matrix20d& K) {
    flush();
    const Matrix20d full = lower_.selfadjointView<Eigen::Lower>();
    K += full;
  }

 private:
  static constexpr int kBatch = 4;
  using Stack = Eigen::Matrix<double, 8 * kBatch, kShellElementDofs>;

  void flush() {
    if (points_ == 0) return;
    B_.bottomRows(8 * (kBatch - points_)).setZero();  // rows of a partial batch
    for (int j = 0; j < kShellElementDofs; ++j)
      for (int i = j; i < kShellElementDofs; ++i) lower_(i, j) += B_.col(i).dot(CB_.col(j));
    points_ = 0;
  }

  const Matrix8d& C_;
  Stack B_, CB_;
  Matrix20d lower_ = Matrix20d::Zero();
  int points_ = 0;
};

// The evaluated integration points of one call with their weights dA = w |X,xi x X,eta| (paper
// eq 54). At most 4 x 4 points.
struct IntegrationPoints {
  int n = 0;
  std::array<Quad4Evaluation::Point, 16> point;
  std::array<double, 16> xi, eta, dA;
};

IntegrationPoints integration_points(const Quad4Evaluation& element, const GaussRule& rule) {
  IntegrationPoints ip;
  for (int i = 0; i < rule.n; ++i)
    for (int j = 0; j < rule.n; ++j, ++ip.n) {
      ip.xi[ip.n] = rule.x[i];
      ip.eta[ip.n] = rule.x[j];
      ip.point[ip.n] = element.at(rule.x[i], rule.x[j]);
      ip.dA[ip.n] = rule.w[i] * rule.w[j] * ip.point[ip.n].frame.area;
    }
  return ip;
}

// Exact static condensation of the EAS membrane parameters (eas_membrane.hpp, quad4_shell.hpp).
// The energy 1/2 sum (E + Gh alpha)^T C (E + Gh alpha) dA, Gh = [G; 0] (membrane rows only), is
// W_c + alpha^T b + 1/2 alpha^T H alpha with H = sum G^T A_mm G dA and b = sum G^T (C E)_m dA,
// where (C E)_m = A_mm e_m + A_mb kappa carries the membrane-bending coupling. Its minimum
// alpha = -H^-1 b is added to the membrane strains of every point, which then give the energy
// W_c - 1/2 b^T H^-1 b and (envelope theorem, dW/dalpha = 0) the force sum B^T C E dA. Since
// dalpha/dq = -H^-1 L with L = db/dq = sum G^T (C B)_m dA, the tangent gains -L^T H^-1 L; the
// geometric terms come with the enhanced resultants C E in compute_at_state.
void condense_eas_membrane(const Matrix8d& C, bool tangent, IntegrationPoints& ip, Matrix20d& K) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
  Eigen::Vector4d b = Eigen::Vector4d::Zero();
  Eigen::Matrix<double, kEasMembraneModes, kShellElementDofs> L;
  L.setZero();
  for (int k = 0; k < ip.n; ++k) {
    const auto& p = ip.point[k];
    const Eigen::Matrix<double, kEasMembraneModes, 3> Gt = ip.dA[k] * p.G.transpose();
    H.noalias() += Gt * C.topLeftCorner<3, 3>() * p.G;
    b.noalias() += Gt * (C.topRows<3>() * p.E);
    if (tangent) {
      const Eigen::Matrix<double, 3, kShellElementDofs> CB = C.topRows<3>().lazyProduct(p.B);
      L.noalias() += Gt.lazyProduct(CB);
    }
  }
  const Eigen::LLT<Eigen::Matrix4d> H_inv(H);
  if (H_inv.info() != Eigen::Success)
    throw_input(
        "shell element with EAS membrane: the membrane stiffness A_R(0:3, 0:3) is not "
        "positive definite (H = int G^T A_mm G dA is singular)");
  const Eigen::Vector4d alpha = -H_inv.solve(b);
  for (int k = 0; k < ip.n; ++k) ip.point[k].E.head<3>() += ip.point[k].G * alpha;
  if (!tangent) return;
  const Eigen::Matrix<double, kEasMembraneModes, kShellElementDofs> H_inv_L = H_inv.solve(L);
  K.noalias() -= L.transpose().lazyProduct(H_inv_L);
}

}  // namespace

Quad4Options mitc4_options() {
  return {"mitc4", ShapeSet::kBilinear, ShearTreatment::kMitc4, 2, MembraneTreatment::kEas4};
}

Quad4Options mitc4_plain_options() {
  return {"mitc4-plain", ShapeSet::kBilinear, ShearTreatment::kMitc4, 2,
          MembraneTreatment::kBilinear};
}

Quad4Options bernstein4_options() {
  return {"bernstein4", ShapeSet::kBernstein, ShearTreatment::kPlain, 4};
}

Quad4Shell::Quad4Shell(Quad4Options options) : options_(std::move(options)) {
  gauss_rule(options_.gauss_points);  // validates
}

void Quad4Shell::compute_at_state(const ElementGeometry& geometry,
                                  const std::array<NodeState, 4>& nodes, const ShellLaw& law,
                                  const ElementRequest& request, ElementResponse& response) const {
  const Matrix8d C = law_matrix(law);
  Quad4Evaluation element(options_, geometry, nodes);
  IntegrationPoints ip = integration_points(element, gauss_rule(options_.gauss_points));
  response.force.setZero();
  response.tangent.setZero();
  response.energy = 0;
  if (options_.membrane == MembraneTreatment::kEas4)
    condense_eas_membrane(C, request.tangent, ip, response.tangent);
  MaterialTangent material(C);
  for (int k = 0; k < ip.n; ++k) {
    const auto& p = ip.point[k];
    const double dA = ip.dA[k];
    const Vector8d S = C * p.E;  // [N; Q], shell_law.hpp
    response.energy += 0.5 * p.E.dot(S) * dA;
    if (request.force) response.force.noalias() += p.B.transpose() * (dA * S);
    if (request.tangent) {
      material.add(p.B, dA);
      element.add_geometric(ip.xi[k], ip.eta[k], p.kin, dA * p.frame.L.transpose() * S);
    }
  }
  if (!request.tangent) return;
  material.add_to(response.tangent);
  element.finish_geometric(response.tangent);
}

void Quad4Shell::compute(const ElementGeometry& geometry, const std::array<NodeState, 4>& nodes,
                         const ShellLaw& law, Kinematics kinematics, const ElementRequest& request,
                         ElementResponse& response) const {
  if (kinematics == Kinematics::kNonlinear) {
    compute_at_state(geometry, nodes, law, request, response);
    return;
  }
  const auto ref = reference_states(geometry);
  compute_at_state(geometry, ref, law, {false, true}, response);
  const Vector20d q = linear_dofs(ref, nodes);
  const Vector20d f = response.tangent * q;
  response.energy = 0.5 * q.dot(f);
  response.force = request.force ? f : Vector20d::Zero();
  if (!request.tangent) response.tangent.setZero();
}

ElementStrains Quad4Shell::strains_at_nodes(const ElementGeometry& geometry,
                                            const std::array<NodeState, 4>& nodes,
                                            Kinematics kinematics) const {
  const bool linear = kinematics == Kinematics::kLinear;
  const auto ref = reference_states(geometry);
  const Quad4Evaluation element(options_, geometry, linear ? ref : nodes);
  const Vector20d q = linear ? linear_dofs(ref, nodes) : Vector20d::Zero();
  // Values at the 2x2 Gauss points (corner order), extrapolated with the bilinear functions
  // through those points: node i sits at (sqrt 3 xi_i, sqrt 3 eta_i) in Gauss-point coordinates.
  const double g = 1 / std::sqrt(3.0);
  std::array<Vector8d, 4> at_gauss;
  for (int k = 0; k < 4; ++k) {
    const auto p = element.at(g * kCornerXi[k], g * kCornerEta[k]);
    at_gauss[k] = linear ? Vector8d(p.B * q) : p.E;
  }
  ElementStrains out;
  for (int i = 0; i < 4; ++i) {
    const Shape4 L = evaluate_shape4(ShapeSet::kBilinear, kCornerXi[i] / g, kCornerEta[i] / g);
    Vector8d e = Vector8d::Zero();
    for (int k = 0; k < 4; ++k) e += L.N(k) * at_gauss[k];
    out.R[i] = e.head<6>();
    out.gamma[i] = e.tail<2>();
  }
  return out;
}

}  // namespace si
