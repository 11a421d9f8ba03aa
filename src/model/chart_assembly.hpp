// The shell's internal force and tangent at chart coordinates x (model/shell_chart.hpp),
// assembled at most once per x. KINSOL asks for the Jacobian at the point of its last residual,
// and one force + tangent assembly costs less than a force assembly followed by a second one
// with the tangent. Shared by the continuation problems of src/analysis (indentation, load).
#pragma once

#include <vector>

#include "model/assembler.hpp"
#include "model/shell_chart.hpp"

namespace si {

class ChartAssembly {
 public:
  // Keeps references to the assembler and the chart (same mesh and dof map).
  ChartAssembly(const Assembler& assembler, const ShellChart& chart);

  // Force and tangent at x, the prescribed translations at prescribed_scale times their values
  // (ShellChart::states); reused if the last assembly was at the same x and scale. An element's
  // error propagates and leaves nothing cached.
  const Assembly& at(const Eigen::VectorXd& x, double prescribed_scale = 1.0);
  // Force and energy at x, the tangent only if the cache already holds x (output of a point
  // that is not where the solver stood).
  const Assembly& force_at(const Eigen::VectorXd& x, double prescribed_scale = 1.0);
  // Drops the cached assembly: after the chart was re-based (ShellChart::rebase) the same x is
  // another state.
  void forget() { x_.resize(0); }
  // Node states of the last at() / force_at().
  const std::vector<NodeState>& states() const { return states_; }
  // Assemblies actually computed (cache misses), with and without the tangent.
  long tangent_assemblies() const { return tangent_assemblies_; }
  long force_assemblies() const { return force_assemblies_; }

 private:
  const Assembly& assemble(const Eigen::VectorXd& x, double prescribed_scale, bool tangent);

  const Assembler& assembler_;
  const ShellChart& chart_;
  Assembly assembly_;
  std::vector<NodeState> states_;
  Eigen::VectorXd x_;  // chart point of the cached assembly (empty: none)
  double prescribed_scale_ = 1.0;
  bool has_tangent_ = false;
  long tangent_assemblies_ = 0;
  long force_assemblies_ = 0;
};

}  // namespace si
