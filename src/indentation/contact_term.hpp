// A part of the indentation problem beyond the shell (indentation_problem.hpp), in the manner of
// MFEM's NonlinearForm integrators: each term owns a block of unknowns and as many rows of
//     F(z, h) = [ r(x) - sum of the terms' forces on the shell ; the terms' own rows ],
// adds its forces to the shell rows, its entries to the Jacobian (its rows, its columns, its
// share of the shell block) and, if it can, its rows to the condensed preconditioner of the
// Krylov solver (contact_jacobian_solver.hpp). The problem holds them in a list and loops; it
// knows no term by name. The terms today: the nodal gaps (nodal_gaps.hpp) or the weighted gaps
// with the paper's interpolated traction (weighted_gaps.hpp), and a local law: the power law's
// approach alpha (power_law_approach.hpp) or the thin layer (thin_layer.hpp). A new one (a
// support frame under the shell, friction) is one file and a line in contact_terms.cpp.
//
// Calls come in the order of the problem's methods, and a term may rely on it: add_shell_force
// then residual (residual()), add_shell_force then add_jacobian (factorize()).
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "continuation/problem.hpp"
#include "core/sparse.hpp"
#include "indentation/contact_jacobian_solver.hpp"
#include "indentation/indentation_state.hpp"
#include "indentation/row_coupling.hpp"
#include "shell/director.hpp"

namespace si {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

// The point a term is asked about: all unknowns, the depth and the shell's node states there.
struct TermPoint {
  const cont::Vector& z;
  double h;
  const std::vector<NodeState>& states;
};

// The position of entry (row, col) in J's values; an input error if it is not in the pattern.
int value_slot(const SparseMatrix& J, int row, int col);

class ContactTerm {
 public:
  virtual ~ContactTerm() = default;

  // Its unknowns (and rows); they start at first() in z and F (the problem's layout).
  virtual int size() const = 0;
  int first() const { return first_; }
  void place(int first) { first_ = first; }
  Eigen::Ref<const cont::Vector> unknowns(const cont::Vector& z) const {
    return z.segment(first_, size());
  }

  // Jacobian pattern: its entries (values 0) in its rows and columns and in the shell block.
  virtual void add_pattern(Triplets& t) const = 0;
  // Finds the value slots of those entries in the assembled pattern.
  virtual void locate(const SparseMatrix& J) = 0;

  // r_free -= its forces on the shell's free dofs.
  virtual void add_shell_force(const TermPoint&, cont::Vector&) {}
  // Its rows' couplings to each other's unknowns kept out of J's pattern (row_coupling.hpp;
  // members numbered among its own rows), as of the last add_jacobian. Empty: none.
  virtual RowCoupling row_coupling() const { return {}; }
  // Its rows of F.
  virtual void residual(const TermPoint& p, cont::Vector& F) = 0;
  // Its entries into J's values (J zeroed, then the shell's K, before any term). Condensable
  // terms append one row per unknown to `condensed` when it is given (the Krylov solver's).
  virtual void add_jacobian(const TermPoint& p, double* J,
                            std::vector<ContactJacobianRow>* condensed) = 0;
  // Its rows of dF/dh (out is zero on entry).
  virtual void residual_p(const TermPoint&, cont::Vector&) {}
  // Whether its rows can join the Krylov solver's condensed preconditioner (each row's gradient
  // on one node's dofs; rows may couple each other's multipliers: coupled_rows.hpp); otherwise
  // the problem uses a direct LU.
  virtual bool condensable() const { return false; }
  // Whether its one unknown, whose row and column couple every contact row (a power law's
  // alpha), may instead border the Krylov solver's matrix: GMRES keeps it and the preconditioner
  // eliminates it by block elimination (contact_jacobian_solver.hpp). Such a term comes last in z.
  virtual bool borders() const { return false; }

  // Its active constraints appended to the problem's signature (1 active, 0 not).
  virtual void signature(const TermPoint&, std::vector<int>&) const {}
  // The gradients, with respect to the shell's free dofs (spatial increments, before the chart),
  // of its strongly active constraints, one row each from row multiplier_index.size() on, and for
  // each row the index in z of its multiplier appended to `multiplier_index` (the tangent
  // restricted to the active constraints, for stability: docs/theory/continuation.md 12).
  virtual void active_gradients(const TermPoint&, Triplets&,
                                std::vector<int>& /*multiplier_index*/) const {}
  // Drops what one solve hands the next (e.g. Newton guesses), so that a resumed run, which starts
  // without them, repeats the uninterrupted one bit for bit (cont::Problem::reset_solver_caches).
  virtual void reset_caches() {}
  // What reset_caches() would drop, to be put back after a computation off the path (the
  // stability analysis re-evaluates the gaps): the path is then the same with it as without.
  virtual std::vector<double> caches() const { return {}; }
  virtual void restore_caches(std::vector<double>) {}
  // After an accepted point: grows the term (new unknowns appended to its block, zero). True if
  // its size changed; the problem then lays z out again.
  virtual bool adapt(const TermPoint&) { return false; }

  // Its results at a point: quantities(), cheap (no gap), for the continuation's monitors;
  // outputs(), everything else.
  virtual void quantities(const TermPoint&, IndentationState&) const {}
  virtual void outputs(const TermPoint&, IndentationState&) const {}

 private:
  int first_ = 0;
};

}  // namespace si
