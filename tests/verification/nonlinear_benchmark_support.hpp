// Shared set-up of the geometrically nonlinear shell benchmarks (Sze, Liu & Lo 2004; reference
// data in ../shared/benchmarks/nonlinear.md): one load-controlled run of the production Newton
// driver (analysis/static_run.hpp) with the mitc4 element, and the comparison of recorded
// displacements with a tabulated load-displacement path.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "../verification_record.hpp"
#include "analysis/static_run.hpp"
#include "model/plate_meshes.hpp"
#include "model/supports.hpp"
#include "shell/shell_element.hpp"

namespace si::verification {

// The converged steps of one run, the final state and the wall time of solve().
struct BenchmarkRun {
  std::vector<StepResult> steps;
  std::vector<NodeState> state;
  double seconds = 0;

  int total_iterations() const {
    int n = 0;
    for (const StepResult& s : steps) n += s.iterations;
    return n;
  }
  int max_iterations() const {
    int n = 0;
    for (const StepResult& s : steps) n = std::max(n, s.iterations);
    return n;
  }
  // The step converged at this load factor; nullptr (and a test failure) if there is none.
  const StepResult* at(double load_factor) const {
    for (const StepResult& s : steps)
      if (std::abs(s.load_factor - load_factor) < 1e-9) return &s;
    ADD_FAILURE() << "no converged step at load factor " << load_factor;
    return nullptr;
  }
};

// Runs run_static (mitc4, nonlinear kinematics) from the reference state to load factor 1.
// The settings' record_nodes say which displacements each step keeps. One assembly thread:
// ctest runs tests side by side (-j2), and the assembled values do not depend on the thread
// count (assembler.hpp).
inline BenchmarkRun run_mitc4_nonlinear(const Mesh& mesh, const std::vector<Support>& supports,
                                        const Loads& loads, const ShellLaw& law,
                                        const StaticSettings& settings) {
  const DofMap dofs = make_dof_map(mesh, supports);
  const auto element = make_shell_element(ElementType::kMitc4);
  BenchmarkRun run;
  const auto start = std::chrono::steady_clock::now();
  StaticResult result =
      run_static(mesh, dofs, *element, law, Kinematics::kNonlinear, loads, settings, {}, 1);
  EXPECT_EQ(result.failure, "");
  run.state = std::move(result.state);
  run.steps = std::move(result.steps);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

// Long runs (the reference meshes where a coarser one is tested by default) only when the
// environment variable SHELLINDENT_LONG_TESTS is set to a non-empty value other than 0.
inline bool long_tests_enabled() {
  const char* value = std::getenv("SHELLINDENT_LONG_TESTS");
  return value != nullptr && *value != '\0' && std::string(value) != "0";
}

// Cantilever strip of Sze, Liu & Lo (2004) sections 3.1 and 3.2: length L along x, width b,
// n x 1 elements, clamped at x = 0. The two tip nodes (x = L) are recorded in this order.
struct CantileverStrip {
  Mesh mesh;
  std::vector<Support> supports;
  std::vector<int> tip_nodes;
};

inline CantileverStrip cantilever_strip(double L, double b, int n) {
  CantileverStrip c;
  c.mesh = rectangular_plate_mesh(L, b, n, 1);
  c.supports = {{SupportKind::kClamped, "edge_x0", -1, {}}};
  c.tip_nodes = c.mesh.node_sets.at("edge_x1");
  return c;
}

// Mean displacement of the recorded nodes of a step (the tip nodes of a strip).
inline Vector3d mean_displacement(const StepResult& s) {
  Vector3d sum = Vector3d::Zero();
  for (const Vector3d& u : s.displacements) sum += u;
  return sum / double(s.displacements.size());
}

// Allowed error max(relative |reference|, absolute).
struct Tolerance {
  double relative = 0;
  double absolute = 0;
  double allowed(double reference) const {
    return std::max(relative * std::abs(reference), absolute);
  }
};

// One column of a reference table and how to read the same quantity from a converged step.
// Errors are printed in % of error_scale (named error_scale_name), or of the reference value if
// error_scale is 0.
struct Column {
  std::string name;
  std::vector<double> reference;
  std::function<double(const StepResult&)> computed;
  double error_scale = 0;
  std::string error_scale_name;
};

// Checks every column at every tabulated load factor against its tolerance and prints the
// comparison (load factor, then reference / computed / error in % per column, see Column) for
// the verification report, and records each comparison in table `table` of the report
// (verification_record.hpp). Returns the largest error as a fraction of the allowed one.
inline double expect_path_matches(const std::string& table, const std::string& source,
                                  const std::string& title, const BenchmarkRun& run,
                                  const std::vector<double>& load_factors,
                                  const std::vector<Column>& columns, const Tolerance& tolerance) {
  std::printf("%s: %zu steps, %d Newton iterations (at most %d per step), %.2f s\n", title.c_str(),
              run.steps.size(), run.total_iterations(), run.max_iterations(), run.seconds);
  std::printf("  load  ");
  for (const Column& c : columns) std::printf("| %-8s ref  computed  err%% ", c.name.c_str());
  std::printf("\n");
  double worst = 0;
  for (std::size_t i = 0; i < load_factors.size(); ++i) {
    const StepResult* step = run.at(load_factors[i]);
    if (step == nullptr) continue;
    std::printf("  %5.3f ", load_factors[i]);
    for (const Column& c : columns) {
      const double ref = c.reference[i], value = c.computed(*step);
      const double error = value - ref;
      const double scale = c.error_scale > 0 ? c.error_scale : std::abs(ref);
      std::printf("| %13.3f %9.4f %6.2f ", ref, value, scale > 0 ? 100 * error / scale : 0.0);
      EXPECT_LE(std::abs(error), tolerance.allowed(ref))
          << title << ", " << c.name << " at load factor " << load_factors[i] << ": reference "
          << ref << ", computed " << value;
      worst = std::max(worst, std::abs(error) / tolerance.allowed(ref));
      char check[64];
      std::snprintf(check, sizeof check, "%s at load factor %.3f", c.name.c_str(), load_factors[i]);
      test::record_verification({table, check, ref, value, tolerance.allowed(ref) / scale, source,
                                 test::ErrorScale::kCustom, scale,
                                 c.error_scale > 0 ? c.error_scale_name : "reference"});
    }
    std::printf("\n");
  }
  return worst;
}

}  // namespace si::verification
