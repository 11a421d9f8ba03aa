// Cost of the damage monitors along a path (issue 16's budget: failure indices at every converged
// point cost at most 20 % of a 1e4-unknown cap path): the source paper's cap ([0/0]2S, full
// model, ~1e4 shell unknowns at mesh (0.92, 1.43) mm), nonlinear kinematics, natural continuation
// 0.1 mm steps to the given depth, run twice through `shellindent run`'s driver: without a
// `damage:` section and with `damage: {criteria: [hashin, delamination]}` (refined recovery at
// the contact candidates), the same run otherwise. Counters: both CPU times, their ratio, the
// monitored nodes, the onset depths. Arguments: (size_apex, size_edge) in 0.01 mm, depth in
// 0.1 mm. Run: cmake --build build-bench --target bench_damage && build-bench/bench/bench_damage
// Figures: docs/performance.md, "Damage monitors".
#include <benchmark/benchmark.h>

#include <string>

#include "analysis/indentation_run.hpp"
#include "io/case_file.hpp"
#include "paper_cap_case.hpp"

namespace si {
namespace {

CaseFile paper_cap(const benchmark::State& st, bool damage) {
  return parse_case_file(
      bench::paper_cap_yaml(st, "",
                            "path: {method: natural, depth_max: " +
                                std::to_string(st.range(2) / 10.0) + " mm, step: 0.1 mm}\n" +
                                (damage ? "damage: {criteria: [hashin, delamination]}\n" : "")),
      "bench_damage");
}

void BM_DamageOverhead(benchmark::State& st) {
  for (auto _ : st) {
    IndentationSetup plain(paper_cap(st, false), 1);
    IndentationSetup damaged(paper_cap(st, true), 1);
    PathResult a, b;
    const double without = bench::cpu_seconds_of_path(plain, a);
    const double with = bench::cpu_seconds_of_path(damaged, b);
    st.counters["shell_unknowns"] = plain.problem->num_shell_unknowns();
    st.counters["monitored_nodes"] = static_cast<double>(damaged.damage->monitored().size());
    st.counters["without_s"] = without;
    st.counters["with_s"] = with;
    st.counters["ratio"] = with / without;
    st.counters["points"] = static_cast<double>(b.points.size());
    for (const DamageOnset& o : b.damage.onsets)
      st.counters[std::string("onset_depth_mm_") + criterion_name(o.criterion)] = o.depth;
    if (!a.completed || !b.completed) st.SkipWithError("a path stopped");
  }
}

}  // namespace
}  // namespace si

BENCHMARK(si::BM_DamageOverhead)->Args({92, 143, 20})->Unit(benchmark::kMillisecond)->Iterations(1);
