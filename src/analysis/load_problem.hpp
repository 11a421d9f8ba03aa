// A load-controlled shell as a continuation problem in the load factor lambda
// (continuation/problem.hpp): the equilibrium of a geometrically nonlinear shell under dead
// loads that grow proportionally,
//     F(x, lambda) = f_int(x) - lambda f_ext = 0        (free dofs),
// x the shell's chart coordinates (model/shell_chart.hpp). The Jacobian is exact,
// dF/dx = K T(x) + D(x, F) (the chart transform of shell_chart.hpp), and dF/dlambda = -f_ext.
// The pseudo-arclength method follows the path through limit points of the load (snap-through)
// and of the displacement (snap-back), which load control cannot (Riks 1979; Crisfield 1981).
// Dead loads only (point, line, nodal moment, dead pressure); supports with zero values.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "continuation/problem.hpp"
#include "model/assembler.hpp"
#include "model/chart_assembly.hpp"
#include "model/dof_map.hpp"
#include "model/loads.hpp"
#include "model/shell_chart.hpp"
#include "model/supports.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

// A monitored displacement: the mean of u . direction over the nodes of a node set, mm.
struct DisplacementMonitor {
  std::string name;
  std::string node_set;
  Vector3d direction = Vector3d::UnitZ();
};

struct LoadProblemOptions {
  std::vector<DisplacementMonitor> displacements;               // monitors after "load_factor"
  LinearSolverKind linear_solver = LinearSolverKind::kUmfpack;  // umfpack | klu: K T + D is
                                                                // unsymmetric
  int threads = 0;  // element assembly (0 = OpenMP default)
};

class LoadProblem : public cont::Problem {
 public:
  // Keeps references to mesh and element. Throws an input error for follower loads,
  // invalid loads, supports or monitor node sets.
  LoadProblem(const Mesh& mesh, const std::vector<Support>& supports, const ShellElement& element,
              const ShellLaw& law, const Loads& loads, LoadProblemOptions options);
  ~LoadProblem() override;

  int size() const override;
  bool residual(const cont::Vector& x, double lambda, cont::Vector& F) override;
  bool factorize(const cont::Vector& x, double lambda) override;
  bool solve(cont::Vector& b) override;
  // -f_ext on the free dofs (exact: the loads are dead).
  bool residual_p(const cont::Vector& x, double lambda, cont::Vector& out) override;
  // Arclength metric: the mean square of the chart coordinates, <a, b> = a.b / n (mm^2 for the
  // translations; the rotations, in rad, are small against them), so an arclength step is the
  // RMS nodal displacement increment; the load factor enters with Settings::parameter_weight (mm
  // per unit load factor).
  double inner(const cont::Vector& a, const cont::Vector& b) const override;
  // "load_factor", then the displacement monitors in options order.
  std::vector<std::string> monitor_names() const override;
  cont::Vector monitors(const cont::Vector& x, double lambda) override;

  // The undeformed state (the solution at lambda = 0).
  cont::Vector initial_point() const { return cont::Vector::Zero(size()); }
  std::vector<NodeState> node_states(const cont::Vector& x) const;
  const DofMap& dofs() const { return dofs_; }
  // f_ext on the free dofs, at load factor 1.
  const Eigen::VectorXd& load_vector() const { return load_; }

 private:
  LoadProblemOptions options_;
  DofMap dofs_;
  Assembler assembler_;
  ShellChart chart_;
  ChartAssembly shell_;                          // force and tangent at the last x
  Eigen::VectorXd load_;                         // free dofs
  std::vector<std::vector<int>> monitor_nodes_;  // per displacement monitor
  SparseMatrix jacobian_;
  std::unique_ptr<LinearSolver> solver_;
};

}  // namespace si
