// Small indentation models shared by the analysis tests: coarse versions of the paper's cap.
#pragma once

#include <cmath>
#include <memory>
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
    // One assembly thread unless asked: on a loaded 2-core CI machine OpenMP's spin-waiting
    // made the nonlinear solves 4-10 times slower.
    if (options.threads == 0) options.threads = 1;
    problem = std::make_unique<IndentationProblem>(model, *indenter, pose.direction, options);
  }
};

}  // namespace si::testing
