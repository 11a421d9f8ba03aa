// Small indentation models shared by the analysis tests: coarse versions of the paper's cap.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "contact/indenter_factory.hpp"
#include "continuation/kinsol_corrector.hpp"
#include "indentation/indentation_problem.hpp"
#include "indentation/linear_indentation.hpp"
#include "io/case_file.hpp"
#include "model/shell_model.hpp"

namespace si::testing {

// The paper's cap (clamped, base radius 25 mm, R = 80.9 mm, t = 3.8 mm, 12.7 mm sphere on the
// outer face) with a coarse mesh; `extra` YAML lines override or add keys.
inline CaseFile coarse_cap_case(const std::string& kinematics, const std::string& layup,
                                const std::string& symmetry = "full", double size_apex = 2.0,
                                double size_edge = 4.0) {
  const std::string yaml =
      "material: paper-carbon-epoxy\n"
      "laminate: {layup: \"" +
      layup +
      "\", ply_thickness: 0.475 mm, reference: mid}\n"
      "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
      "mesh: {element: mitc4, size_apex: " +
      std::to_string(size_apex) + " mm, size_edge: " + std::to_string(size_edge) +
      " mm, refine_radius: 10 mm, symmetry: " + symmetry + "}\n" + "kinematics: " + kinematics +
      "\n" + "indenter: {shape: sphere, radius: 12.7 mm}\n";
  return parse_case_file(yaml, "coarse_cap.yaml");
}

// One isotropic ply of thickness t (mm; E = 70 GPa, nu = 0.3 inline, the material of
// point-loads.md 4.2) with the given shell and mesh (YAML flow maps), pressed by a rigid sphere of
// radius `sphere_radius` (mm) on the face `surface` (outer | mid).
constexpr double kIsotropicE = 70000.0;  // MPa
constexpr double kIsotropicNu = 0.3;

inline CaseFile isotropic_indentation_case(double t, const std::string& shell,
                                           const std::string& mesh, const std::string& kinematics,
                                           double sphere_radius, const std::string& surface) {
  const std::string yaml = "material: {type: isotropic, E: " + std::to_string(kIsotropicE) +
                           " MPa, nu: " + std::to_string(kIsotropicNu) + "}\n" +
                           "laminate: {layup: \"[0]\", ply_thickness: " + std::to_string(t) +
                           " mm}\n" + "shell: " + shell + "\nmesh: " + mesh +
                           "\nkinematics: " + kinematics +
                           "\nindenter: {shape: sphere, radius: " + std::to_string(sphere_radius) +
                           " mm}\ncontact: {surface: " + surface + "}\n";
  return parse_case_file(yaml, "isotropic_indentation.yaml");
}

// Settings of the full KINSOL solve at one depth, tight enough for the KKT checks (1e-8 of the
// force scale): relative tolerance 1e-12 on residuals scaled by kappa (N per mm of gap).
inline cont::NewtonSettings tight_kinsol_settings(const IndentationProblem& p) {
  cont::NewtonSettings s;
  s.relative_tolerance = 1e-12;
  s.residual_scale = p.stiffness_scale();
  s.max_iterations = 40;
  s.max_step = 1e12;
  return s;
}

// The coarse quarter cap with a nonlinear depth path to depth_max (mm) by `method`.
inline CaseFile coarse_cap_path_case(const std::string& layup, PathMethod method, double depth_max,
                                     double step, double step_max) {
  CaseFile c = coarse_cap_case("nonlinear", layup, "quarter");
  c.path.method = method;
  c.path.depth_max = depth_max;
  c.path.step = step;
  c.path.step_min = 1e-4;
  c.path.step_max = step_max;
  return c;
}

// A model, its indenter (above the apex, moving along -z) and the problem, kept together.
struct IndentationFixture {
  CaseFile case_file;
  ShellModel model;
  std::unique_ptr<Indenter> indenter;
  std::unique_ptr<IndentationProblem> problem;

  explicit IndentationFixture(CaseFile c, IndentationOptions options = IndentationOptions{})
      : case_file(std::move(c)), model(build_shell_model(case_file)) {
    IndenterPose pose;
    const Vector3d apex = model.mesh.nodes[model.apex_node()];
    pose.position = apex + Vector3d(0, 0, case_file.indenter.radius + 5.0);
    indenter = make_indenter(case_file.indenter, pose);
    options.contact_offset = contact_face_offset(case_file);
    options.frame_offset = back_face_offset(case_file);
    // One assembly thread unless asked: on a loaded 2-core CI machine OpenMP's spin-waiting
    // made the nonlinear solves 4-10 times slower.
    if (options.threads == 0) options.threads = 1;
    problem = std::make_unique<IndentationProblem>(model, *indenter, pose.direction, options);
  }
};

// The Jacobian checks recover v by solving with J: exactly (GMRES to 1e-12), not to the Newton
// forcing term the runs use (IndentationOptions::krylov_tolerance).
inline IndentationOptions exact_solves(IndentationOptions o = {}) {
  o.krylov_tolerance = 1e-12;
  return o;
}

// A point off the solution: small random shell coordinates, positive multipliers on the
// candidates near the apex, at depth 0.3 mm (so several gaps are near zero or negative), and the
// local approach `alpha` (mm) with a power-law local contact. `multiplier_min` (N) keeps the
// multipliers off the NCP function's kink, where its curvature ~ 1/|(lambda, kappa g)| makes the
// central difference's second-order error exceed the check's tolerance (a support frame's many
// rows with gaps near zero).
inline cont::Vector trial_point(const IndentationProblem& p, unsigned seed, double alpha = 0.1,
                                double multiplier_min = 0.0) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> uni(-1, 1);
  cont::Vector z = p.initial_point();
  const int nf = p.num_shell_unknowns();
  for (int i = 0; i < nf; ++i) z[i] = 0.02 * uni(gen);
  for (int i = nf; i < z.size(); ++i) z[i] = multiplier_min + 50.0 * (1 + uni(gen));
  if (p.num_local_unknowns() > 0) z[p.layout().alpha_index()] = alpha;
  return z;
}

// The whole Jacobian (shell tangent, contact stiffness, chart transform, NCP rows) against
// central differences of the residual with step `eps`.
inline void expect_jacobian_matches_fd(IndentationProblem& p, double h_depth, double approach = 0.1,
                                       double multiplier_min = 0.0, double eps = 1e-6) {
  const cont::Vector z = trial_point(p, 7, approach, multiplier_min);
  ASSERT_TRUE(p.factorize(z, h_depth));
  // J e_j by solving: J^-1 (J e_j) = e_j is awkward; compare J v to the FD directional
  // derivative for a few random directions v instead, using J v = J J^-1 (J v)... so apply J
  // through the residual's linearisation: (F(z + eps v) - F(z - eps v)) / (2 eps) = J v, and
  // check J^-1 of that returns v.
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (int trial = 0; trial < 3; ++trial) {
    cont::Vector v(z.size());
    // Lengths (shell coordinates, alpha) of order 1, multipliers of order 100 N.
    const int alpha = p.num_local_unknowns() ? p.layout().alpha_index() : -1;
    for (int i = 0; i < v.size(); ++i)
      v[i] = uni(gen) * (i < p.num_shell_unknowns() || i == alpha ? 1.0 : 100.0);
    cont::Vector fp, fm;
    ASSERT_TRUE(p.residual(z + eps * v, h_depth, fp));
    ASSERT_TRUE(p.residual(z - eps * v, h_depth, fm));
    cont::Vector Jv = (fp - fm) / (2 * eps);
    ASSERT_TRUE(p.factorize(z, h_depth));
    ASSERT_TRUE(p.solve(Jv));
    EXPECT_LT((Jv - v).cwiseAbs().maxCoeff() / v.cwiseAbs().maxCoeff(), 1e-6) << trial;
  }
}

}  // namespace si::testing
