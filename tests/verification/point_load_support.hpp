// Set-up shared by the point-load verification tests: an isotropic shell described by a case
// file (so the tests also exercise build_shell_model), run by the static solver.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "analysis/static_run.hpp"
#include "core/constants.hpp"
#include "io/case_file.hpp"
#include "model/assembler.hpp"
#include "model/shell_model.hpp"

namespace si::testing {

// Isotropic material of the point-load tests (point-loads.md 4.2 uses E = 70 GPa, nu = 0.3).
constexpr double kE = 70000.0;  // MPa
constexpr double kNu = 0.3;

// Bending stiffness D = E t^3 / (12 (1 - nu^2)).
inline double plate_rigidity(double t) {
  return kE * t * t * t / (12.0 * (1.0 - kNu * kNu));
}

// A case of one isotropic ply of thickness t_mm (mm) with the given shell, mesh, kinematics and
// load lines (YAML flow maps).
inline std::string isotropic_case(double t_mm, const std::string& shell, const std::string& mesh,
                                  const std::string& kinematics, const std::string& load) {
  return "material: {type: isotropic, E: " + std::to_string(kE) +
         " MPa, nu: " + std::to_string(kNu) +
         "}\n"
         "laminate: {layup: \"[0]\", ply_thickness: " +
         std::to_string(t_mm) + " mm}\nshell: " + shell + "\nmesh: " + mesh +
         "\nkinematics: " + kinematics + "\nload: " + load + "\n";
}

struct StaticRun {
  ShellModel model;
  std::vector<StepResult> steps;
  std::vector<NodeState> state;  // last converged
  double strain_energy = 0;      // of an independent assembly at the final state, N mm
  Eigen::VectorXd applied;       // nodal load vector at load factor 1 (all dofs), N
};

// Builds the model of the case and runs it with the apex node recorded.
inline StaticRun run_static_case(const std::string& yaml) {
  StaticRun run;
  const CaseFile c = parse_case_file(yaml, "point_load_case");
  run.model = build_shell_model(c);
  const ShellModel& m = run.model;
  const DofMap dofs = make_dof_map(m.mesh, m.supports, m.displacements);
  StaticSettings settings = c.static_run;
  settings.steps = c.load->steps;
  settings.tolerance = 1e-10;
  settings.record_nodes = {m.apex_node()};
  StaticResult result =
      run_static(m.mesh, dofs, *m.element, m.law, m.kinematics, m.loads, settings);
  EXPECT_EQ(result.failure, "");
  run.state = std::move(result.state);
  run.steps = std::move(result.steps);
  const Assembler assembler(m.mesh, dofs, *m.element, m.law, m.kinematics);
  Assembly a = assembler.make_assembly();
  assembler.assemble(run.state, {true, false}, a);
  run.strain_energy = a.energy;
  run.applied = fixed_load_vector(m.mesh, m.loads);
  return run;
}

// Deflection along -z of a node.
inline double deflection(const StaticRun& run, int node) {
  return -run.state[node].u.z();
}

}  // namespace si::testing
