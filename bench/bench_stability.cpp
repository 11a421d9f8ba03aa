// Cost of path.stability (issue 15's budget: the stability of every converged point costs at most
// 25 % of a 1e4-unknown cap path and 40 % at 1e5): the cap of bench/cases/cap_path_1e4.yaml
// ([0/0]2S, full model, nonlinear, pseudo-arclength 0 to the given depth, 0.1 mm steps), run
// twice through `shellindent run`'s driver in the same process, without and with
// `path.stability: true`, the same run otherwise (the path is the same to round-off: the points
// are compared). Counters: both times (process CPU, so that other jobs on the machine count
// less), their ratio, the points, the analyses by each route and the Cholesky factorizations of
// the Krylov preconditioner in each run. Arguments: (size_apex,
// size_edge) in 0.01 mm, depth in 0.1 mm; 1e4: (92, 143), 1e5: (29, 46).
// Run: cmake --build build-bench --target bench_stability && build-bench/bench/bench_stability
// Figures: docs/performance.md, "Stability along the path".
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/indentation_run.hpp"
#include "io/case_file.hpp"
#include "paper_cap_case.hpp"

namespace si {
namespace {

CaseFile paper_cap(const benchmark::State& st, bool stability) {
  return parse_case_file(bench::paper_cap_yaml(st, ", symmetry: full",
                                               "kinematics: nonlinear\n"
                                               "indenter: {shape: sphere, radius: 12.7 mm}\n"
                                               "contact: {surface: outer, solver: kinsol}\n"
                                               "path: {method: pseudo_arclength, depth_max: " +
                                                   std::to_string(st.range(2) / 10.0) +
                                                   " mm, step: 0.1 mm, stability: " +
                                                   (stability ? "true" : "false") + "}\n"),
                         "bench_stability");
}

void BM_StabilityOverhead(benchmark::State& st) {
  for (auto _ : st) {
    IndentationSetup plain(paper_cap(st, false), 1);
    IndentationSetup analysed(paper_cap(st, true), 1);
    PathResult a, b;
    const double without = bench::cpu_seconds_of_path(plain, a);
    const double with = bench::cpu_seconds_of_path(analysed, b);
    st.counters["shell_unknowns"] = plain.problem->num_shell_unknowns();
    st.counters["without_cpu_s"] = without;
    st.counters["with_cpu_s"] = with;
    st.counters["ratio"] = with / without;
    st.counters["points"] = static_cast<double>(b.points.size());
    // The same path to round-off (the analysis refreshes the Krylov preconditioner): the largest
    // difference in force and depth relative to the path's largest, or 1 if the points differ.
    double difference = a.points.size() == b.points.size() ? 0.0 : 1.0;
    const double force = a.points.empty() ? 1.0 : std::abs(a.points.back().state.force);
    const double depth = a.points.empty() ? 1.0 : std::abs(a.points.back().state.depth);
    for (std::size_t i = 0; difference < 1.0 && i < a.points.size(); ++i)
      difference =
          std::max({difference, std::abs(a.points[i].state.force - b.points[i].state.force) / force,
                    std::abs(a.points[i].state.depth - b.points[i].state.depth) / depth});
    st.counters["path_difference"] = difference;
    st.counters["analyses_from_preconditioner"] =
        static_cast<double>(analysed.problem->counters().stability_from_preconditioner);
    st.counters["analyses_direct"] =
        static_cast<double>(analysed.problem->counters().stability_direct);
    st.counters["cholesky_without"] =
        static_cast<double>(plain.problem->solver_counters().cholesky);
    st.counters["cholesky_with"] =
        static_cast<double>(analysed.problem->solver_counters().cholesky);
    if (!a.completed || !b.completed) st.SkipWithError("a path stopped");
  }
}

}  // namespace
}  // namespace si

BENCHMARK(si::BM_StabilityOverhead)
    ->Args({92, 143, 100})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
// ~1e5 unknowns (about 4 minutes of CPU for the pair): build-bench/bench/bench_stability
// --benchmark_filter=BM_StabilityOverhead/29
BENCHMARK(si::BM_StabilityOverhead)
    ->Args({29, 46, 20})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
