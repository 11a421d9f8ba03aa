// Timing of indentation paths on the source paper's cap ([0/0]2S carbon/epoxy, base radius
// 25 mm, R = 80.9 mm, clamped, full model, 12.7 mm sphere on the outer face), 0 to 10 mm in
// 100 depth steps of 0.1 mm, through the same driver as `shellindent run`
// (analysis/indentation_run.hpp). Issue 4's targets: the paper's mesh (286 nodes), linear
// kinematics, 100 steps under 0.05 s; nonlinear kinematics, 1e4 dofs, 100 steps under 10 s.
// Counters: nodes, shell unknowns, contact candidates, Newton iterations per step,
// factorizations and residuals per step, time per step. Arguments: (size_apex, size_edge) in
// 0.01 mm, then the contact Jacobian's solver (0 = UMFPACK, 1 = KLU, 2 = Cholesky-preconditioned
// GMRES, the default) and, for the nonlinear path, the depth in 0.1 mm and the assembly threads.
// Run: cmake -S . -B build-bench -G Ninja -DSHELLINDENT_BENCH=ON -DSHELLINDENT_TESTS=OFF &&
//      cmake --build build-bench --target bench_contact && build-bench/bench/bench_contact
// Figures: docs/performance.md, "Contact".
#include <benchmark/benchmark.h>

#include <string>

#include "analysis/indentation_run.hpp"
#include "io/case_file.hpp"
#include "paper_cap_case.hpp"

namespace si {
namespace {

CaseFile paper_cap(const benchmark::State& st, const std::string& kinematics, double depth) {
  return parse_case_file(
      bench::paper_cap_yaml(st, "",
                            "kinematics: " + kinematics + "\npath: {method: natural, depth_max: " +
                                std::to_string(depth) + " mm, step: 0.1 mm}\n"),
      "bench_contact");
}

void report(benchmark::State& st, const IndentationSetup& s, const PathResult& r) {
  const double steps = static_cast<double>(r.points.size() - 1);
  long iterations = 0;
  for (const PathPoint& p : r.points) iterations += p.iterations;
  const IndentationCounters c = s.problem->counters();
  st.counters["nodes"] = s.model.mesh.num_nodes();
  st.counters["shell_unknowns"] = s.problem->num_shell_unknowns();
  st.counters["candidates"] = static_cast<double>(s.problem->candidates().size());
  st.counters["steps"] = steps;
  st.counters["newton_per_step"] = iterations / steps;
  st.counters["factorizations_per_step"] = c.factorizations / steps;
  st.counters["residuals_per_step"] = c.residuals / steps;
  st.counters["assemblies_per_step"] = c.tangent_assemblies / steps;
  st.counters["force_assemblies_per_step"] = c.force_assemblies / steps;
  const ContactJacobianCounters k = s.problem->solver_counters();
  st.counters["lu_fallbacks"] = static_cast<double>(k.lu_fallbacks);
  st.counters["choleskys_per_step"] = k.cholesky / steps;
  st.counters["gmres_products_per_solve"] =
      k.krylov_solves > 0 ? static_cast<double>(k.krylov_products) / k.krylov_solves : 0.0;
  st.counters["force_at_end_N"] = r.points.back().state.force;
  if (!r.completed) st.SkipWithError(("path stopped: " + r.reason).c_str());
}

// 100 depths: K factorization, Schur complement, the LCP per depth and the per-point results
// (reactions, energy, curvature, pressures). The model set-up (mesh, VAM section, candidate
// search) is not timed.
void BM_LinearPath(benchmark::State& st) {
  for (auto _ : st) {
    st.PauseTiming();
    IndentationSetup s(paper_cap(st, "linear", 10.0), 1);
    st.ResumeTiming();
    const PathResult r = run_indentation_path(s);
    st.PauseTiming();
    report(st, s, r);
    st.ResumeTiming();
  }
}

// 100 depths by natural continuation with the KINSOL corrector (setup included, small).
void BM_NonlinearPath(benchmark::State& st) {
  for (auto _ : st) {
    const JacobianSolverKind solvers[] = {JacobianSolverKind::kUmfpack, JacobianSolverKind::kKlu,
                                          JacobianSolverKind::kPreconditionedKrylov};
    IndentationSetup s(paper_cap(st, "nonlinear", st.range(3) / 10.0),
                       static_cast<int>(st.range(4)), solvers[st.range(2)]);
    const PathResult r = run_indentation_path(s);
    st.PauseTiming();
    report(st, s, r);
    st.ResumeTiming();
  }
}

}  // namespace
}  // namespace si

// (200, 330): 1269 nodes? no - chosen sizes are printed as counters; ~286 nodes at (300, 450).
BENCHMARK(si::BM_LinearPath)
    ->Args({300, 450, 0})
    ->Args({92, 143, 0})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(si::BM_NonlinearPath)
    ->Args({300, 450, 0, 100, 1})
    ->Args({300, 450, 1, 100, 1})
    ->Args({300, 450, 2, 100, 1})
    ->Args({92, 143, 0, 100, 1})
    ->Args({92, 143, 1, 100, 1})
    ->Args({92, 143, 2, 100, 1})
    ->Args({92, 143, 0, 20, 1})
    ->Args({92, 143, 2, 20, 1})
    ->Args({92, 143, 2, 100, 2})
    ->Args({29, 46, 2, 20, 2})  // ~1e5 unknowns, 0-2 mm: time and Newton iterations per step
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
