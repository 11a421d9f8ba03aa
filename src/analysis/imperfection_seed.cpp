#include "analysis/imperfection_seed.hpp"

#include <string>

#include "analysis/indentation_run.hpp"
#include "analysis/mode_field.hpp"
#include "core/error.hpp"

namespace si {
namespace {

// The case whose path gives the mode: the same shell without the imperfection, with stability,
// without damage monitors (they do not change the path).
IndentationCase perfect_case(const IndentationCase& c) {
  IndentationCase p = c;
  p.path.imperfection.reset();
  p.path.stability = true;
  p.damage.reset();
  return p;
}

// The mode's nodal translations with the reproducible sign: its largest component positive.
Eigen::MatrixXd signed_shape(const Eigen::MatrixXd& translations) {
  Eigen::Index row = 0, col = 0;
  translations.cwiseAbs().maxCoeff(&row, &col);
  return translations(row, col) < 0 ? Eigen::MatrixXd(-translations) : translations;
}

}  // namespace

ImperfectionSeed seed_imperfection(const IndentationCase& c, int threads,
                                   JacobianSolverKind linear_solver) {
  const Where where{c.file, "path.imperfection", "", 0};
  ImperfectionSeed seed;
  seed.spec = *c.path.imperfection;
  IndentationSetup perfect(perfect_case(c), threads, linear_solver);
  // Traced until the count of negative eigenvalues first differs from the start's: the change's
  // event is located on the segment before that point.
  int start_count = -2;
  cont::Vector last_z;
  const PathCallback stop_after_change = [&](const PathPoint& p, const cont::Vector& z) {
    last_z = z;
    if (start_count == -2) start_count = p.negative_eigenvalues;
    return p.negative_eigenvalues == start_count;
  };
  PathControl control;
  control.critical_points = false;
  const PathResult r = run_indentation_path(perfect, stop_after_change, control);
  seed.perfect_points = static_cast<int>(r.points.size());
  if (r.points.empty())
    throw_input("the perfect shell's path, which gives the mode, did not start: " + r.reason,
                where);
  IndentationProblem& problem = *perfect.problem;
  cont::Vector z = last_z;
  double h = r.points.back().state.depth;
  for (const cont::Event& e : r.events) {
    if (e.type != cont::EventType::kStabilityChange) continue;
    const cont::Vector at = in_present_layout(e.x, problem);  // the candidates may have grown
    if (at.size() == 0) continue;
    z = at;
    h = e.p;
    seed.at_stability_change = true;
    seed.criticality = e.criticality;
    break;
  }
  seed.depth = h;
  seed.force = problem.evaluate(z, h).force;
  cont::Stability stability;
  if (!problem.stability(z, h, seed.spec.mode, stability) ||
      static_cast<int>(stability.modes.size()) < seed.spec.mode)
    throw_input("mode " + std::to_string(seed.spec.mode) +
                    " of the restricted tangent could not be computed at depth " +
                    std::to_string(h) + " mm of the perfect path",
                where);
  const std::size_t k = static_cast<std::size_t>(seed.spec.mode - 1);
  seed.eigenvalue = stability.eigenvalues(static_cast<Eigen::Index>(k));
  seed.shape =
      seed.spec.amplitude * signed_shape(mode_translations(problem.dofs(), stability.modes[k],
                                                           perfect.model.mesh.num_nodes()));
  return seed;
}

}  // namespace si
