#include "indentation/jacobian_solver.hpp"

#include <utility>

#include "indentation/coupled_lu.hpp"

namespace si {
namespace {

// A sparse LU of the whole Jacobian (with its rows' couplings), made anew (pattern analysed)
// after a pattern change.
class DirectJacobianSolver final : public JacobianSolver {
 public:
  explicit DirectJacobianSolver(LinearSolverKind kind) : lu_(kind) {}
  bool wants_condensed_rows() const override { return false; }
  void pattern_changed() override { lu_.forget(); }
  void reset() override { pattern_changed(); }
  void factorize(const SparseMatrix& J, int num_shell,
                 const std::vector<ShellChart::RotationBlock>&,
                 const std::vector<ContactJacobianRow>&, int, RowCoupling coupling) override {
    lu_.factorize(J, num_shell, coupling);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) override { return lu_.solve(rhs); }

 private:
  CoupledLu lu_;
};

// The preconditioned Krylov solver; its factor survives pattern changes (appended rows).
class KrylovJacobianSolver final : public JacobianSolver {
 public:
  KrylovJacobianSolver(double kappa, double tolerance)
      : solver_(kappa, LinearSolverKind::kUmfpack, tolerance) {}
  bool wants_condensed_rows() const override { return true; }
  void reset() override { solver_.forget_preconditioner(); }
  void factorize(const SparseMatrix& J, int num_shell,
                 const std::vector<ShellChart::RotationBlock>& rotations,
                 const std::vector<ContactJacobianRow>& rows, int border,
                 RowCoupling coupling) override {
    solver_.factorize(J, num_shell, rotations, rows, border, std::move(coupling));
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) override { return solver_.solve(rhs); }
  ContactJacobianCounters counters() const override { return solver_.counters(); }
  std::optional<PenalizedShell> penalized_shell(const std::vector<int>& rows) override {
    if (!solver_.refresh_penalized(rows)) return std::nullopt;
    return PenalizedShell{
        [this](const cont::Vector& in, cont::Vector& out) { out = solver_.solve_shell_block(in); },
        solver_.chart_gradients(rows)};
  }

 private:
  ContactJacobianSolver solver_;
};

}  // namespace

std::unique_ptr<JacobianSolver> make_jacobian_solver(JacobianSolverKind kind, bool condensable,
                                                     double kappa, double krylov_tolerance) {
  if (kind == JacobianSolverKind::kPreconditionedKrylov && condensable)
    return std::make_unique<KrylovJacobianSolver>(kappa, krylov_tolerance);
  return std::make_unique<DirectJacobianSolver>(
      kind == JacobianSolverKind::kKlu ? LinearSolverKind::kKlu : LinearSolverKind::kUmfpack);
}

}  // namespace si
