// The settings of a load-controlled static run (static_run.hpp), filled by io/ from the case
// file's `load.steps` and `static:` section (docs/case-file.md) and by the command.
#pragma once

#include <vector>

#include "analysis/path_spec.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

struct StaticSettings {
  PathMethod method = PathMethod::kNatural;
  int steps = 10;  // natural: nominal load increments of 1 / steps
  // pseudo_arclength: arclength steps (mm), the weight of lambda in them (mm per unit load
  // factor), the load factor at which the run ends and the largest number of steps.
  double step = 0.1;
  double step_min = 1e-4;
  double step_max = 1.0;
  double parameter_weight = 1.0;
  double load_factor_max = 1.0;
  int max_steps = 1000;

  int max_iterations = 25;  // Newton iterations per step
  double tolerance = 1e-8;  // relative to the force scale (above)
  bool halve_on_failure = true;
  int max_halvings = 5;                                         // natural
  LinearSolverKind linear_solver = LinearSolverKind::kCholmod;  // linear kinematics: cholmod |
                                                                // umfpack; nonlinear: umfpack
  std::vector<int> record_nodes;  // nodes whose displacement each StepResult keeps
  // The stability of every point (LoadProblem::stability; docs/theory/continuation.md 12) and
  // its changes located as events, classified as limit point or bifurcation, with their mode.
  bool stability = false;

  // Throws an input error naming the bad field (static.<field>).
  void validate() const;
};

}  // namespace si
