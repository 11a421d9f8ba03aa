// Element-level verification of the 4-node shell (mitc4 unless stated): rigid-body motions,
// force and tangent against finite differences, linear mode vs nonlinear mode, spectrum.
#include "shell/quad4_shell.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/error.hpp"

namespace si {
namespace {

// A curved, warped element (nodes off a plane, directors tilted away from the normals).
ElementGeometry warped_geometry() {
  ElementGeometry g;
  g.X = {Vector3d(0, 0, 0), Vector3d(1.1, 0.1, 0.12), Vector3d(1.0, 0.9, -0.08),
         Vector3d(-0.1, 1.0, 0.1)};
  g.D = {Vector3d(-0.1, 0.05, 1).normalized(), Vector3d(0.1, -0.05, 1).normalized(),
         Vector3d(0.08, 0.12, 1).normalized(), Vector3d(-0.12, 0.1, 1).normalized()};
  g.material_axis = Vector3d(1, 0.3, 0);
  return g;
}

// A laminate-like law with membrane-bending coupling (B != 0) and anisotropy, positive definite.
ShellLaw coupled_law() {
  ShellLaw law = isotropic_shell_law(1000, 0.3, 0.3);
  Eigen::Matrix3d B;
  B << 3, 1, -1, 1, 2, 0.5, -1, 0.5, -2;
  law.A_R.topRightCorner<3, 3>() = B;
  law.A_R.bottomLeftCorner<3, 3>() = B.transpose();
  law.A_R(0, 1) = law.A_R(1, 0) = 20;
  law.A_R(3, 5) = law.A_R(5, 3) = 0.5;
  law.G(0, 1) = law.G(1, 0) = 10;
  return law;
}

std::array<NodeState, 4> reference_nodes(const ElementGeometry& g) {
  std::array<NodeState, 4> s;
  for (int i = 0; i < 4; ++i) s[i] = reference_node_state(g.D[i]);
  return s;
}

// Random deformed state: displacements ~0.1 (element size 1), rotations ~0.3 rad.
std::array<NodeState, 4> deformed_nodes(const ElementGeometry& g) {
  auto s = reference_nodes(g);
  const double r[4][5] = {{0.05, -0.08, 0.1, 0.3, -0.2},
                          {-0.1, 0.07, -0.04, -0.25, 0.32},
                          {0.08, 0.1, 0.12, 0.15, 0.28},
                          {-0.03, -0.09, -0.1, -0.33, -0.1}};
  for (int i = 0; i < 4; ++i) {
    s[i].u = Vector3d(r[i][0], r[i][1], r[i][2]);
    rotate_node(s[i], r[i][3], r[i][4]);
  }
  return s;
}

// Perturbs dof k of the element by h: a translation, or a rotation about the current axis.
std::array<NodeState, 4> perturbed(std::array<NodeState, 4> s, int k, double h) {
  const int node = k / kShellNodeDofs, dof = k % kShellNodeDofs;
  if (dof < 3)
    s[node].u(dof) += h;
  else
    rotate_node(s[node], dof == 3 ? h : 0, dof == 4 ? h : 0);
  return s;
}

ElementResponse compute(const ShellElement& e, const ElementGeometry& g,
                        const std::array<NodeState, 4>& s, const ShellLaw& law,
                        Kinematics kin = Kinematics::kNonlinear) {
  ElementResponse r;
  e.compute(g, s, law, kin, {}, r);
  return r;
}

// Consistency of force and tangent with the energy: both elements (the Bernstein element is
// consistent, only its shape functions are defective).
class Quad4ShellConsistency : public ::testing::TestWithParam<ElementType> {};
// Rigid-body invariance: only elements whose shapes are a partition of unity.
class Quad4ShellRigidMotion : public ::testing::TestWithParam<ElementType> {};

// Finite rigid motion (translation + 1.2 rad rotation) of a curved element: zero strain energy
// and zero internal force to round-off (Simo & Fox strains are invariant under rigid motions).
TEST_P(Quad4ShellRigidMotion, FiniteRigidMotionIsStressFree_Nonlinear) {
  const auto element = make_shell_element(GetParam());
  const ElementGeometry g = warped_geometry();
  const ShellLaw law = coupled_law();
  const Matrix3d Q = rotation_matrix(Vector3d(0.5, -0.9, 0.6));
  const Vector3d c(3, -2, 5);
  auto s = reference_nodes(g);
  for (int i = 0; i < 4; ++i) {
    s[i].u = Q * g.X[i] + c - g.X[i];
    s[i].d = Q * s[i].d;
    s[i].v1 = Q * s[i].v1;
    s[i].v2 = Q * s[i].v2;
  }
  const ElementResponse rigid = compute(*element, g, s, law);
  const ElementResponse ref = compute(*element, g, deformed_nodes(g), law);
  std::cout << element->name() << " rigid motion: energy " << rigid.energy << " (deformed "
            << ref.energy << "), |f| " << rigid.force.norm() << " (deformed " << ref.force.norm()
            << ")\n";
  EXPECT_LT(std::abs(rigid.energy), 1e-12 * ref.energy);
  EXPECT_LT(rigid.force.norm(), 1e-12 * ref.force.norm());
}

// Force = dW/dq by central differences of the energy (rotations about the current v1, v2).
TEST_P(Quad4ShellConsistency, ForceIsEnergyGradient_FiniteDifferences) {
  const auto element = make_shell_element(GetParam());
  const ElementGeometry g = warped_geometry();
  const ShellLaw law = coupled_law();
  const auto s = deformed_nodes(g);
  const ElementResponse r = compute(*element, g, s, law);
  Vector20d fd;
  const double h = 1e-5;
  for (int k = 0; k < kShellElementDofs; ++k)
    fd(k) = (compute(*element, g, perturbed(s, k, h), law).energy -
             compute(*element, g, perturbed(s, k, -h), law).energy) /
            (2 * h);
  const double err = (fd - r.force).norm() / r.force.norm();
  std::cout << element->name() << " force vs FD of energy: relative error " << err << "\n";
  EXPECT_LT(err, 1e-6);
}

// Tangent = derivative of the force. Finite rotations do not commute, so the finite-difference
// derivative of the force along rotate_node perturbations equals the energy Hessian only up to
// an antisymmetric part proportional to the moment residual ([S_i, S_j] d = (t_i x t_j) x d).
// The tangent is the symmetric Hessian, so it is compared with the symmetric part. With the two
// rotation axes orthogonal to d here, t_i x t_j is parallel to d and the antisymmetric part
// vanishes too; it is measured and reported.
TEST_P(Quad4ShellConsistency, TangentIsForceDerivative_FiniteDifferences) {
  const auto element = make_shell_element(GetParam());
  const ElementGeometry g = warped_geometry();
  const ShellLaw law = coupled_law();
  const auto s = deformed_nodes(g);
  const ElementResponse r = compute(*element, g, s, law);
  Matrix20d fd;
  const double h = 1e-6;
  for (int k = 0; k < kShellElementDofs; ++k)
    fd.col(k) = (compute(*element, g, perturbed(s, k, h), law).force -
                 compute(*element, g, perturbed(s, k, -h), law).force) /
                (2 * h);
  const Matrix20d sym = (fd + fd.transpose()) / 2;
  const double err = (sym - r.tangent).norm() / r.tangent.norm();
  const double skew = (fd - fd.transpose()).norm() / 2 / r.tangent.norm();
  std::cout << element->name() << " tangent vs FD of force: relative error " << err
            << ", antisymmetric part " << skew << "\n";
  EXPECT_LT(err, 1e-6);
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-13 * r.tangent.norm());
}

// kLinear is the nonlinear element linearised at the reference state: same tangent there, and
// force = K0 q for states built with rotate_node from the reference.
TEST_P(Quad4ShellConsistency, LinearModeIsNonlinearTangentAtReference) {
  const auto element = make_shell_element(GetParam());
  const ElementGeometry g = warped_geometry();
  const ShellLaw law = coupled_law();
  const auto ref = reference_nodes(g);
  const ElementResponse lin = compute(*element, g, ref, law, Kinematics::kLinear);
  const ElementResponse non = compute(*element, g, ref, law, Kinematics::kNonlinear);
  EXPECT_LT((lin.tangent - non.tangent).norm(), 1e-14 * non.tangent.norm());
  const auto s = deformed_nodes(g);
  Vector20d q;
  const double r[4][2] = {{0.3, -0.2}, {-0.25, 0.32}, {0.15, 0.28}, {-0.33, -0.1}};
  for (int i = 0; i < 4; ++i) q.segment<5>(5 * i) << s[i].u, r[i][0], r[i][1];
  const ElementResponse at_q = compute(*element, g, s, law, Kinematics::kLinear);
  EXPECT_LT((at_q.force - lin.tangent * q).norm(), 1e-12 * at_q.force.norm());
  EXPECT_NEAR(at_q.energy, 0.5 * q.dot(lin.tangent * q), 1e-12 * at_q.energy);
}

// Infinitesimal rigid modes (3 translations, 3 rotations) are in the kernel of K0.
TEST_P(Quad4ShellRigidMotion, InfinitesimalRigidModesAreStressFree_Linear) {
  const auto element = make_shell_element(GetParam());
  const ElementGeometry g = warped_geometry();
  const ShellLaw law = coupled_law();
  const auto ref = reference_nodes(g);
  const Matrix20d K = compute(*element, g, ref, law, Kinematics::kLinear).tangent;
  for (int mode = 0; mode < 6; ++mode) {
    Vector20d q;
    const Vector3d w = mode >= 3 ? Vector3d(Vector3d::Unit(mode - 3)) : Vector3d::Zero();
    const Vector3d c = mode < 3 ? Vector3d(Vector3d::Unit(mode)) : Vector3d::Zero();
    for (int i = 0; i < 4; ++i)
      q.segment<5>(5 * i) << c + w.cross(g.X[i]), w.dot(ref[i].v1), w.dot(ref[i].v2);
    EXPECT_LT((K * q).norm(), 1e-13 * K.norm() * q.norm()) << "mode " << mode;
  }
}

// mitc4 = MITC4 + EAS-4 membrane (its condensation enters energy, force and tangent: the coupled
// law's B != 0 makes the condensed parameters depend on the curvatures too), mitc4-plain = MITC4
// with the bilinear membrane.
INSTANTIATE_TEST_SUITE_P(Elements, Quad4ShellConsistency,
                         ::testing::Values(ElementType::kMitc4, ElementType::kMitc4Plain,
                                           ElementType::kBernstein4));
INSTANTIATE_TEST_SUITE_P(Elements, Quad4ShellRigidMotion,
                         ::testing::Values(ElementType::kMitc4, ElementType::kMitc4Plain));

// A free flat MITC4 element (with and without EAS): exactly 6 zero eigenvalues (rigid modes, the
// drilling rotation being a membrane rigid mode), 14 positive, no spurious mechanism. A distorted
// quadrilateral too, since the EAS modes are built from its centre Jacobian.
class Mitc4FreeElement : public ::testing::TestWithParam<ElementType> {};

TEST_P(Mitc4FreeElement, FreeFlatElementHasSixRigidModes) {
  const auto element = make_shell_element(GetParam());
  ElementGeometry g;
  g.X = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)};
  for (auto& D : g.D) D = Vector3d::UnitZ();
  const ShellLaw law = isotropic_shell_law(1000, 0.3, 0.1);
  const ElementGeometry distorted = [&] {
    ElementGeometry d = g;
    d.X = {Vector3d(0, 0, 0), Vector3d(1.3, 0.1, 0), Vector3d(0.9, 0.8, 0), Vector3d(0.2, 1.1, 0)};
    return d;
  }();
  for (const ElementGeometry* shape : {static_cast<const ElementGeometry*>(&g), &distorted}) {
    const Matrix20d K =
        compute(*element, *shape, reference_nodes(*shape), law, Kinematics::kLinear).tangent;
    const Eigen::SelfAdjointEigenSolver<Matrix20d> eig(K);
    const auto& l = eig.eigenvalues();
    const double scale = l(19);
    std::cout << element->name() << (shape == &g ? " square" : " distorted")
              << " free element spectrum / max: 6th " << l(5) / scale << ", 7th " << l(6) / scale
              << "\n";
    EXPECT_LT(std::abs(l(5)) / scale, 1e-13);
    EXPECT_GT(l(6) / scale, 1e-6);  // the smallest bending mode, ~ (t/L)^2 times the membrane
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, Mitc4FreeElement,
                         ::testing::Values(ElementType::kMitc4, ElementType::kMitc4Plain));

// t1 = projection of material_axis on the tangent plane; an axis along the normal falls back to
// X,xi. On a flat square aligned with x: e1 + 0.5 e3 and e3 give the same stiffness as e1, while
// e2 (the laminate turned by 90 deg) changes it for an anisotropic law.
TEST(Mitc4Shell, MaterialAxisIsProjectedOnTheTangentPlane) {
  const auto element = make_shell_element(ElementType::kMitc4);
  const ShellLaw law = coupled_law();
  ElementGeometry g;
  g.X = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)};
  for (auto& D : g.D) D = Vector3d::UnitZ();
  auto stiffness = [&](const Vector3d& axis) {
    g.material_axis = axis;
    return compute(*element, g, reference_nodes(g), law, Kinematics::kLinear).tangent;
  };
  const Matrix20d K = stiffness(Vector3d::UnitX());
  EXPECT_LT((stiffness(Vector3d(1, 0, 0.5)) - K).norm(), 1e-14 * K.norm());
  EXPECT_LT((stiffness(Vector3d::UnitZ()) - K).norm(), 1e-14 * K.norm());
  EXPECT_GT((stiffness(Vector3d::UnitY()) - K).norm(), 1e-3 * K.norm());
}

// Each type builds its element, named as the case file writes it (io/case_file.cpp reads the
// names; an unknown one is refused there, test_case_file_errors.cpp).
TEST(ShellElementFactory, EachTypeBuildsItsNamedElement) {
  EXPECT_EQ(make_shell_element(ElementType::kMitc4)->name(), "mitc4");
  EXPECT_EQ(make_shell_element(ElementType::kMitc4Plain)->name(), "mitc4-plain");
  EXPECT_EQ(make_shell_element(ElementType::kBernstein4)->name(), "bernstein4");
}

TEST(Mitc4Shell, DegenerateGeometryIsAnInputError) {
  const auto element = make_shell_element(ElementType::kMitc4);
  const ShellLaw law = isotropic_shell_law(1000, 0.3, 0.1);
  ElementGeometry collapsed;  // all nodes on a line: zero area
  collapsed.X = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0), Vector3d(3, 0, 0)};
  for (auto& D : collapsed.D) D = Vector3d::UnitZ();
  ElementGeometry tangent_director;  // directors in the plane of the element
  tangent_director.X = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)};
  for (auto& D : tangent_director.D) D = Vector3d::UnitX();
  for (const auto* g : {&collapsed, &tangent_director}) {
    ElementResponse r;
    try {
      element->compute(*g, reference_nodes(*g), law, Kinematics::kNonlinear, {}, r);
      ADD_FAILURE() << "accepted degenerate geometry";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::kInput);
      EXPECT_NE(std::string(e.what()).find("degenerate shell element"), std::string::npos);
      std::cout << e.what() << "\n";
    }
  }
}

}  // namespace
}  // namespace si
