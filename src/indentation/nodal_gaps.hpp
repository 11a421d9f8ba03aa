// Nodal contact (contact_rows.hpp): candidate i's gap is its node's gap g_i along the direction
// of travel (contact/node_gap.hpp: exact for nonlinear kinematics, linearised for linear), its
// multiplier a nodal force, and its row couples to that node's five dofs only:
//     shell rows:  r(x) - sum_i lambda_i G_i,    Jacobian [ K - sum_i lambda_i dG_i   -G ]
//                                                          [ phi_b kappa G^T       phi_a ]
// (then the chart transform of the shell columns). Such rows condense onto the shell block: the
// preconditioned Krylov solver can take them (contact_jacobian_solver.hpp).
#pragma once

#include <utility>
#include <vector>

#include "indentation/contact_rows.hpp"

namespace si {

class NodalGaps final : public ContactRows {
 public:
  using ContactRows::ContactRows;

  void add_shell_force(const TermPoint& p, cont::Vector& r_free) override;
  void add_jacobian(const TermPoint& p, double* J,
                    std::vector<ContactJacobianRow>* condensed) override;
  bool condensable() const override { return true; }
  SparseMatrix gap_matrix(const TermPoint& reference) const override;

 private:
  double gap_value(int i, const TermPoint& p, double depth) const override;
  bool hits(int i, const TermPoint& p, double depth) const override;
  void gradient(int i, const TermPoint& p, std::vector<std::pair<int, double>>& out) const override;
  double pressure_area(int i) const override;
  void candidates_changed(bool appended) override;
  void reset_caches() override;
  std::vector<double> caches() const override { return touch_guess_; }
  void restore_caches(std::vector<double> guesses) override { touch_guess_ = std::move(guesses); }
  // Candidate i's gap at the face depth; a miss is a far gap. Keeps s(p) as the next guess.
  NodeGap gap(int i, const std::vector<NodeState>& s, double depth, bool derivative) const;

  mutable std::vector<double> touch_guess_;  // per candidate: last s(p), a Newton guess
};

}  // namespace si
