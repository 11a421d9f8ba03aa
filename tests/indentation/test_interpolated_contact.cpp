// The paper's contact option (indentation/interpolated_contact.hpp; issue #4 item 3): interpolated
// traction t_N = N~ t-bar_N with weighted gaps and the F-bar coupling (paper eqs 13-19, 72-76).
// References: the nodal multipliers (a different method: node_gap.hpp), exact areas of flat
// plates, uniform strain fields, the full KINSOL solve, and the energy identity of a linear
// frictionless contact problem.
#include <gtest/gtest.h>

#include <numeric>

#include "contact/indenter_factory.hpp"
#include "indentation/interpolated_contact.hpp"
#include "indentation/linear_indentation.hpp"
#include "indentation_test_support.hpp"
#include "model/dof_map.hpp"
#include "model/plate_meshes.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

using testing::coarse_cap_case;
using testing::IndentationFixture;

// A free flat plate [0, 8] x [0, 6] mm (4 x 3 elements in z = 0, directors +z, two interior
// nodes moved in the plane so that the quads are not parallelograms) under a flat punch of radius
// 50 mm covering it, moving along -z from z = 2 mm: every face point is met head-on, so
// a = ds/dp = e = -z and a . n = -1 (travel_gap.hpp).
struct FlatPlate {
  Mesh mesh = distorted(rectangular_plate_mesh(8, 6, 4, 3));
  DofMap dofs{mesh.num_nodes(), {}};
  std::unique_ptr<ShellElement> element = make_shell_element(ElementType::kMitc4);
  Assembler assembler{
      mesh, dofs, *element, isotropic_shell_law(70000, 0.3, 1.0), Kinematics::kLinear, 1};
  std::unique_ptr<Indenter> punch;
  std::vector<int> nodes;

  FlatPlate() {
    IndenterSpec spec;
    spec.shape = IndenterShape::kFlatPunch;
    spec.radius = 50;
    IndenterPose pose;
    pose.position = Vector3d(4, 3, 2);
    punch = make_indenter(spec, pose);
    nodes.resize(mesh.num_nodes());
    std::iota(nodes.begin(), nodes.end(), 0);
  }
  static Mesh distorted(Mesh m) {
    m.nodes[6] += Vector3d(0.3, -0.2, 0);     // node (1, 1)
    m.nodes[13] += Vector3d(-0.25, 0.35, 0);  // node (3, 2)
    return m;
  }
  InterpolatedContact integrate(const InterpolatedContactOptions& options) const {
    return integrate_interpolated_contact(mesh, assembler, *element,
                                          ContactFace{*punch, Vector3d(0, 0, -1), 0.0, 2.0}, nodes,
                                          options);
  }
  // Free-dof vector of the field u = (e1 x, e2 y, 0), director increment (k1 x, k2 y, 0): uniform
  // R = [e1, 0, e2, k1, 0, k2] (vam.md 1: kappa_ab = beta_a,b with delta d = beta on a flat
  // plate), through the linear-mode rotations (a, b) with delta d = -a v2 + b v1.
  Eigen::VectorXd uniform_field(const Vector6d& R) const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(dofs.num_free());
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const Vector3d& X = mesh.nodes[n];
      const NodeState ref = reference_node_state(mesh.directors[n]);
      const Vector3d dd(R[3] * X.x(), R[5] * X.y(), 0);
      const double q[5] = {R[0] * X.x(), R[2] * X.y(), 0, -dd.dot(ref.v2), dd.dot(ref.v1)};
      for (int l = 0; l < 5; ++l) x[dofs.equation(DofMap::dof(n, l))] = q[l];
    }
    return x;
  }
};

// Issue #4 item 3 test 2: with a partition of unity the weights sum to the area of the contact
// face; the plate is 8 mm x 6 mm = 48 mm^2 exactly (its quads are planar, so |x_xi x x_eta| is
// linear in xi, eta and every Gauss rule integrates it exactly).
TEST(InterpolatedContact, WeightsSumToTheFlatPlateArea_48mm2) {
  const FlatPlate plate;
  for (int n : {1, 2, 3}) {
    InterpolatedContactOptions o;
    o.gauss_points = n;
    const InterpolatedContact ic = plate.integrate(o);
    EXPECT_NEAR(ic.w.sum(), 48.0, 1e-12 * 48.0) << n;
    EXPECT_EQ(ic.elements.size(), 12u);
    // The punch face is flat and parallel to the plate: every weighted gap is zero at h = 0.
    EXPECT_LT(ic.g0.cwiseAbs().maxCoeff(), 1e-12);
  }
}

// Issue #4 item 3 test 3: for a uniform strain field R the F-bar part of row i is
// int N_i (a . n)(-R^T Fbar) dA = w_i R^T Fbar exactly (a . n = -1 here). Fbar is an arbitrary
// vector: the identity does not depend on the section.
TEST(InterpolatedContact, FbarRowOfAUniformStrainFieldIsWeightTimesRTFbar) {
  const FlatPlate plate;
  Vector6d R, Fbar;
  R << 2e-3, 0, -1e-3, 4e-4, 0, 3e-4;
  Fbar << 0.11, 0.07, 0.13, 0.021, 0.017, 0.019;
  const Eigen::VectorXd x = plate.uniform_field(R);
  // The element's own strains are the prescribed uniform field (the premise of the check).
  for (int e = 0; e < plate.mesh.num_elements(); ++e) {
    std::vector<NodeState> s = reference_state(plate.mesh);
    const Eigen::VectorXd full = plate.dofs.expand(x, 1.0);
    for (int n : plate.mesh.elements[e]) {
      s[n].u = full.segment<3>(DofMap::dof(n, 0));
      rotate_node(s[n], full[DofMap::dof(n, 3)], full[DofMap::dof(n, 4)]);
    }
    const ElementStrains es = plate.element->strains_at_nodes(
        plate.assembler.geometry(e), plate.assembler.element_states(s, e), Kinematics::kLinear);
    for (int a = 0; a < 4; ++a) EXPECT_LT((es.R[a] - R).cwiseAbs().maxCoeff(), 1e-15) << e;
  }
  for (int n : {2, 3}) {
    InterpolatedContactOptions o;
    o.gauss_points = n;
    const InterpolatedContact plain = plate.integrate(o);
    o.fbar = true;
    o.fbar_top = Fbar;
    const InterpolatedContact coupled = plate.integrate(o);
    const Eigen::VectorXd term = (coupled.C - plain.C) * x;
    const Eigen::VectorXd expected = plain.w * R.dot(Fbar);
    EXPECT_LT((term - expected).cwiseAbs().maxCoeff(), 1e-14 * expected.cwiseAbs().maxCoeff()) << n;
    EXPECT_GT(R.dot(Fbar), 0);  // the check is not 0 = 0
  }
}

// Options of the paper's cap with the interpolated traction (and the section's F-bar).
IndentationOptions interpolated_options(const CaseFile& c, int gauss_points, bool fbar) {
  IndentationOptions o;
  o.interpolated_traction = true;
  o.interpolated.gauss_points = gauss_points;
  o.interpolated.fbar = fbar;
  if (fbar) o.interpolated.fbar_top = analyze_vam(c.laminate).Fbar_top;
  return o;
}

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// Issue #4 item 3 test 1: with the nodal (lumped) rule the weighted gap of node i is w_i times
// its nodal gap, so the option reduces to the nodal multipliers, t-bar_i w_i = lambda_i, to
// round-off. The nodal option is a different code path (node_gap.hpp, per node).
TEST(InterpolatedContact, NodalRuleReducesToTheNodalMultipliers) {
  const CaseFile c = coarse_cap_case("linear", "[45/-45]2S");
  IndentationFixture nodal(c);
  IndentationFixture lumped(c, interpolated_options(c, 0, false));
  ASSERT_EQ(nodal.problem->candidates(), lumped.problem->candidates());
  LinearIndentation a(*nodal.problem), b(*lumped.problem);
  const int nf = nodal.problem->num_shell_unknowns();
  for (double h : {0.5, 1.0, 2.0}) {
    const cont::Vector za = a.solve(h), zb = b.solve(h);
    const IndentationState sb = lumped.problem->evaluate(zb, h);
    Eigen::VectorXd t_times_w(sb.pressures.size());
    const InterpolatedContact ic = integrate_interpolated_contact(
        lumped.model.mesh, lumped.problem->assembler(), *lumped.model.element,
        ContactFace{*lumped.indenter, Vector3d(0, 0, -1), contact_face_offset(c),
                    lumped.problem->first_touch()},
        lumped.problem->candidates(), interpolated_options(c, 0, false).interpolated);
    for (Eigen::Index i = 0; i < t_times_w.size(); ++i)
      t_times_w[i] = sb.pressures[static_cast<std::size_t>(i)] * ic.w[i];
    EXPECT_LT(relative_difference(t_times_w, za.tail(za.size() - nf)), 1e-10) << h;
    EXPECT_LT(relative_difference(zb.head(nf), za.head(nf)), 1e-10) << h;
    EXPECT_GT(za.tail(za.size() - nf).maxCoeff(), 0);
  }
}

// Issue #4 item 3 test 4: with the interpolated traction and the F-bar term, the full KINSOL
// solve of the Fischer-Burmeister system and the linear fast path agree to 1e-10.
TEST(InterpolatedContact, KinsolAndLinearFastPathAgreeWithFbar) {
  const CaseFile c = coarse_cap_case("linear", "[45/-45]2S");
  IndentationFixture f(c, interpolated_options(c, 2, true));
  IndentationProblem& p = *f.problem;
  LinearIndentation fast(p);
  cont::Vector z = p.initial_point();
  const int nf = p.num_shell_unknowns();
  for (double h : {0.3, 1.0, 2.0, 1.4}) {
    const cont::NewtonResult r = cont::solve_at(p, z, h, testing::tight_kinsol_settings(p));
    ASSERT_TRUE(r.converged) << r.reason;
    const cont::Vector zf = fast.solve(h);
    EXPECT_LT(relative_difference(zf.head(nf), z.head(nf)), 1e-10) << h;
    EXPECT_LT(relative_difference(zf.tail(z.size() - nf), z.tail(z.size() - nf)), 1e-10) << h;
    const IndentationState s = p.evaluate(zf, h);
    EXPECT_NEAR(s.force, s.reaction, 1e-9 * s.force);  // the multipliers balance the supports
    EXPECT_GT(s.min_multiplier, -1e-10 * s.force);
  }
}

// Issue #4 item 3 test 5, the energy identity. With linear kinematics the solution minimises
// Pi(h) = min_x max_{t >= 0} 1/2 x^T K x - t^T g~(x, h) and at the solution t^T g~ = 0, so
// Pi(h) = U = 1/2 x^T K x; by the envelope theorem dPi/dh = t^T w = T_N. Hence the indenter work
// int_0^h T_N dh equals the strain energy U of the RM shell, with or without F-bar: the F-bar
// term is part of the gap (it moves the loaded face by -R^T Fbar+), and what it adds to the
// energy, int t+ R^T Fbar+ dA, is cancelled by the complementarity. (The face compliance term
// -1/2 t^T C_L t of vam.md 7.4 is not modelled.) Reference accuracy: the trapezoidal rule over
// the depth grid; its error is estimated by halving the step.
TEST(InterpolatedContact, IndenterWorkEqualsStrainEnergyWithFbar) {
  const CaseFile c = coarse_cap_case("linear", "[45/-45]2S");
  IndentationFixture f(c, interpolated_options(c, 2, true));
  IndentationProblem& p = *f.problem;
  const double depth = 1.5;
  const auto work = [&](int steps) {
    LinearIndentation fast(p);
    double w = 0, previous = 0;
    for (int k = 1; k <= steps; ++k) {
      const double h = depth * k / steps;
      const double force = p.evaluate(fast.solve(h), h).force;
      w += 0.5 * (previous + force) * depth / steps;
      previous = force;
    }
    return w;
  };
  const double coarse = work(30), fine = work(60);
  LinearIndentation fast(p);
  const double energy = p.evaluate(fast.solve(depth), depth).energy;
  EXPECT_GT(energy, 0);
  EXPECT_LT(std::abs(fine - energy), std::abs(coarse - fine)) << fine << " vs " << energy;
}

}  // namespace
}  // namespace si
