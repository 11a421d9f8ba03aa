// Small indentation models shared by the analysis tests: coarse versions of the paper's cap.
#pragma once

#include <memory>
#include <string>

#include "analysis/indentation_problem.hpp"
#include "analysis/shell_model.hpp"
#include "contact/indenter_factory.hpp"
#include "io/case_file.hpp"

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
    problem = std::make_unique<IndentationProblem>(model, *indenter, pose.direction, options);
  }
};

}  // namespace si::testing
