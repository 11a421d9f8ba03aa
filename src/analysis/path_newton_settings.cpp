// path_newton_settings (indentation_run.hpp): the corrector's settings shared by a path's steps,
// the onset search's trial solves and the force-travel re-solves.
#include "analysis/indentation_run.hpp"

namespace si {

cont::NewtonSettings path_newton_settings(const IndentationSetup& s) {
  cont::NewtonSettings n;
  n.relative_tolerance = 1e-10;
  // The force a gap of one depth step would carry: the scale of the equilibrium residual.
  n.residual_scale = s.problem->stiffness_scale() * s.spec.path.step;
  n.max_iterations = kPathMaxIterations;
  // KINSOL's step limit is an L2 length over all unknowns, and the multipliers are forces (N):
  // its default, 1000 max(1, |z0|), cuts the Newton steps of a stiff shell short (measured: 2 %
  // residual decrease per iteration on the paper's cap). Allow any step the line search accepts.
  n.max_step = 1e12;
  // A corrector whose ||R||_2 has fallen by less than 10 % over two iterations gives the step
  // back to the continuation, which halves it: measured on the 250k-unknown cap near 9.6 mm, a
  // creeping corrector cost 12-21 iterations (up to 12 min) before failing anyway; no converged
  // solve of the studies and tests measured had such a stretch (docs/performance.md).
  n.stall_window = 2;
  return n;
}

}  // namespace si
