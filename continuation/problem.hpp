// The generic continuation problem: a residual F(x, p) = 0 in n unknowns x and one parameter p,
// with its Jacobian dF/dx factored and solved by the problem itself (the library never sees a
// matrix), dF/dp, and optional extras (inner product, monitors, a discrete signature, a
// determinant sign, adaptation). The shape follows pacopy/LOCA: the library knows "a problem",
// nothing about shells. Theory: docs/theory/continuation.md.
#pragma once

#include <string>
#include <vector>

#include "continuation/linear_algebra.hpp"
#include "continuation/stability.hpp"

namespace si::cont {

class Problem {
 public:
  virtual ~Problem() = default;
  virtual int size() const = 0;

  // F(x, p) into F (resized by the callee). false = cannot evaluate here (e.g. an inverted
  // element): recoverable, the step is retried smaller.
  virtual bool residual(const Vector& x, double p, Vector& F) = 0;

  // Linearise dF/dx at (x, p) and factor it. false = failure (singular...) -> recoverable.
  virtual bool factorize(const Vector& x, double p) = 0;

  // Solve (dF/dx) y = b in place with the last factorization. false = failure. The solve may be
  // inexact (an iterative solver stopped at a small relative residual): the correctors judge
  // convergence on F itself, and the tangents and events tolerate errors far above roundoff.
  virtual bool solve(Vector& b) = 0;

  // Why the last residual(), factorize() or solve() that returned false failed, in the
  // problem's words (e.g. which factorization and why); empty if not known. The corrector adds
  // it to its failure reason.
  virtual std::string failure() const { return {}; }
  // What unknown (and equation) i is, in the problem's words (e.g. a node's displacement and
  // where the node is), for a failed corrector's report of where its residual is largest;
  // empty if not known.
  virtual std::string unknown_name(int) const { return {}; }

  // dF/dp at (x, p); default: central finite difference of residual() with the relative step
  // h = eps^(1/3) max(1, |p|), which balances the O(h^2) truncation against O(eps/h) roundoff.
  virtual bool residual_p(const Vector& x, double p, Vector& out);

  // Inner product used by the arclength constraint and norms; default a.dot(b). It must be
  // symmetric positive definite and linear (the bordered solve relies on linearity).
  virtual double inner(const Vector& a, const Vector& b) const;

  // Named scalar monitors at a solution (force, curvatures...) for events and output; default
  // none. Monitors must be smooth functions of (x, p) near the branch: their derivatives along
  // the branch are taken by finite differences off the branch (docs/theory/continuation.md).
  virtual std::vector<std::string> monitor_names() const;
  virtual Vector monitors(const Vector& x, double p);
  // The monitors listed in `which` (indices into monitor_names(), ascending), in that order: the
  // derivatives along the branch need only some of them, at points off the branch. A problem
  // with monitors of very different cost overrides it to compute only those; default: a
  // selection from monitors(x, p).
  virtual Vector monitor_subset(const Vector& x, double p, const std::vector<int>& which);

  // A discrete signature (e.g. the contact set) whose change between accepted points is an
  // event; default empty.
  virtual std::vector<int> signature(const Vector& x, double p);

  // Sign of det(dF/dx) from the last factorize() (+1/-1), 0 = unknown (the default). Used only
  // by the optional bifurcation indicator.
  virtual int jacobian_sign();

  // Stability of the converged point (x, p), optional (docs/theory/continuation.md, "Stability"):
  // the number of negative eigenvalues of the symmetric tangent restricted to the problem's
  // constraints and its lowest `modes` eigenpairs, the modes in x. A problem builds it from its
  // matrices with analyse_stability() (stability_analysis.hpp). Called only when a run asks for
  // stability (Settings::stability_modes > 0), after factorize(x, p); it must leave that
  // factorization usable. false = cannot be computed here (recoverable, like factorize()).
  // provides_stability() says whether stability() is implemented (default false; a run asking
  // for stability of a problem without it is refused).
  virtual bool provides_stability() const;
  virtual bool stability(const Vector& x, double p, int modes, Stability& out);

  // A start for the corrector at parameter p on the step out of the point (x_from, p_from), where
  // the problem knows a better one than the predictor's; empty = none (the default). The tangent
  // at a degenerate start sees nothing of what the step changes (an indenter at first touch: one
  // node in contact, the step's solution has several); a simpler model's solution at p (the
  // linear-kinematics one) does. The steppers' fixed-p correctors try it first and fall back to
  // the predictor if the corrector fails from it or does not end on the step (each iteration is
  // counted). A problem with several branches through (x_from, p_from) returns none there.
  virtual Vector corrector_start(const Vector& x_from, double p_from, double p);

  // Called after each accepted point. The problem may change its size (e.g. grow a contact
  // candidate set) and map x to the new size in place; return true if it did (the library then
  // recomputes the tangent at that point, the previous secant/tangent being invalid).
  virtual bool adapt(Vector& x, double p);

  // Called after each periodic checkpoint, and before a resumed run goes on. A problem that
  // carries solver state from one linearisation to the next (e.g. a preconditioner reused while
  // it works) drops it here: a run resumed from the checkpoint starts without it, and from
  // that point on both take the same steps bit for bit. Default: nothing to drop.
  virtual void reset_solver_caches();
};

}  // namespace si::cont
