// Nodal contact (contact_rows.hpp): candidate i's gap is its node's gap g_i along the direction
// of travel (contact/node_gap.hpp: exact for nonlinear kinematics, linearised for linear), its
// multiplier a nodal force, and its row couples to that node's five dofs only:
//     shell rows:  r(x) - sum_i lambda_i G_i,    Jacobian [ K - sum_i lambda_i dG_i   -G ]
//                                                          [ phi_b kappa G^T       phi_a ]
// (then the chart transform of the shell columns). Such rows condense onto the shell block: the
// preconditioned Krylov solver can take them (contact_jacobian_solver.hpp).
// With the F-bar term (set_fbar, linear kinematics; face_thickening.hpp) the gap gains the face's
// rise (a . n) c_i . x, whose row spans the node's elements: the rows no longer condense onto one
// node, and the problem uses the direct LU (as for the interpolated traction). Measured on the
// paper's cap: GMRES preconditioned without the rise's entries took 6x the LU's time.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "indentation/contact_rows.hpp"
#include "indentation/face_thickening.hpp"

namespace si {

class NodalGaps final : public ContactRows {
 public:
  using ContactRows::ContactRows;

  // Adds the F-bar face term with the section's Fbar+, the contact face `offset` mm above the
  // reference surface (before set_candidates).
  void set_fbar(const Vector6d& fbar_top, double offset);

  void add_pattern(Triplets& t) const override;
  void locate(const SparseMatrix& J) override;
  void add_shell_force(const TermPoint& p, cont::Vector& r_free) override;
  void add_jacobian(const TermPoint& p, double* J,
                    std::vector<ContactJacobianRow>* condensed) override;
  // The rows condense on their nodes unless the F-bar term spans more (a non-local law's
  // couplings are eliminated by the preconditioner: coupled_rows.hpp).
  bool condensable() const override { return !thickening_; }
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
  // Candidate i's gap at the face depth, with the face's rise; a miss is a far gap. Keeps s(p)
  // as the next guess.
  NodeGap gap(int i, const TermPoint& p, double depth, bool derivative) const;
  // The F-bar term's gap per unit of the rise row, a . n (0 without the term or off the path).
  double rise_factor(int i, const NodeGap& g) const;

  mutable std::vector<double> touch_guess_;  // per candidate: last s(p), a Newton guess
  std::unique_ptr<FaceThickening> thickening_;
  std::vector<DofRow> rise_rows_;  // per candidate, with thickening_
  // Per candidate and rise-row entry: the value slots (multiplier, eq) and (eq, multiplier).
  std::vector<std::vector<std::pair<int, int>>> rise_slots_;
};

}  // namespace si
