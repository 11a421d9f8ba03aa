// Timing of one tangent assembly + CHOLMOD factorization with the real mitc4 element on the
// source paper's cap ([0/90]2S carbon/epoxy, base radius 25 mm, R = 80.9 mm, clamped, full
// model), meshed for ~1e3, ~1e4 and ~1e5 free dofs. The target: one tangent assembly +
// CHOLMOD factorization of 1e5 dofs under 1 s on 2 cores. Symbolic analysis is done once
// beforehand (a Newton run reuses it); the state is the reference state, nonlinear kinematics.
// Run: cmake -S . -B build-bench -G Ninja -DSHELLINDENT_BENCH=ON -DSHELLINDENT_TESTS=OFF &&
//      cmake --build build-bench --target bench_cap && build-bench/bench/bench_cap
// Figures: docs/performance.md, "Shell assembly and factorization".
#include <benchmark/benchmark.h>

#include <string>

#include "io/case_file.hpp"
#include "model/assembler.hpp"
#include "model/shell_model.hpp"
#include "model/supports.hpp"
#include "solvers/linear_solver.hpp"

namespace si {
namespace {

// The paper's cap with mesh sizes in units of 0.01 mm.
CaseFile paper_cap(long size_apex_cmm, long size_edge_cmm) {
  const std::string text =
      "material: paper-carbon-epoxy\n"
      "laminate: {layup: \"[0/90]2S\", ply_thickness: 0.475 mm}\n"
      "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
      "mesh: {element: mitc4, size_apex: " +
      std::to_string(size_apex_cmm / 100.0) +
      " mm, size_edge: " + std::to_string(size_edge_cmm / 100.0) + " mm, refine_radius: 13 mm}\n";
  return parse_case_file(text, "bench_cap");
}

// (size_apex, size_edge) in 0.01 mm giving ~1e3, ~1e4, ~1e5 free dofs, times 1 and 2 threads.
void sizes_threads(benchmark::internal::Benchmark* b) {
  for (auto [apex, edge] : {std::pair{250L, 400L}, std::pair{92L, 143L}, std::pair{29L, 46L}})
    for (long t : {1L, 2L}) b->Args({apex, edge, t});
}

struct Problem {
  explicit Problem(const benchmark::State& st)
      : model(build_shell_model(paper_cap(st.range(0), st.range(1)))),
        dofs(make_dof_map(model.mesh, model.supports)),
        assembler(model.mesh, dofs, *model.element, model.law, model.kinematics,
                  static_cast<int>(st.range(2))),
        state(reference_state(model.mesh)) {}
  ShellModel model;
  DofMap dofs;
  Assembler assembler;
  std::vector<NodeState> state;
};

void BM_CapAssembly(benchmark::State& st) {
  const Problem p(st);
  Assembly out = p.assembler.make_assembly();
  for (auto _ : st) p.assembler.assemble(p.state, {}, out);
  st.counters["dofs"] = p.dofs.num_free();
}

void BM_CapFactorize(benchmark::State& st) {
  const Problem p(st);
  Assembly out = p.assembler.make_assembly();
  p.assembler.assemble(p.state, {}, out);
  auto solver = make_linear_solver(LinearSolverKind::kCholmod);
  solver->analyze(out.tangent);
  for (auto _ : st) solver->factorize(out.tangent);
  st.counters["dofs"] = p.dofs.num_free();
  st.counters["nnz"] = static_cast<double>(out.tangent.nonZeros());
}

// The target operation.
void BM_CapAssemblyPlusFactorize(benchmark::State& st) {
  const Problem p(st);
  Assembly out = p.assembler.make_assembly();
  p.assembler.assemble(p.state, {}, out);
  auto solver = make_linear_solver(LinearSolverKind::kCholmod);
  solver->analyze(out.tangent);
  for (auto _ : st) {
    p.assembler.assemble(p.state, {}, out);
    solver->factorize(out.tangent);
  }
  st.counters["dofs"] = p.dofs.num_free();
}

BENCHMARK(BM_CapAssembly)->Apply(sizes_threads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CapFactorize)->Apply(sizes_threads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CapAssemblyPlusFactorize)
    ->Apply(sizes_threads)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace si
