// Issue 5's record for the load-controlled path: steps, Newton iterations and linear solves of
// Sze's hinged roofs (sec. 3.8 (a) h = 12.7 and (d) h = 6.35, quarter model, n x n mitc4,
// pseudo-arclength 0 -> P/Pmax = 1.1 through the snap-through and the snap-back) with the
// settings of the verification test (tests/verification/sze_roof_support.hpp). Arguments:
// thickness in 0.01 mm, n, assembly threads.
// Run: cmake -S . -B build-bench -G Ninja -DSHELLINDENT_BENCH=ON -DSHELLINDENT_TESTS=OFF &&
//      cmake --build build-bench --target bench_roof && build-bench/bench/bench_roof
// Figures: docs/performance.md.
#include <benchmark/benchmark.h>

#include "continuation/pseudo_arclength.hpp"
#include "sze_roof_support.hpp"

namespace si {
namespace {

// Forwards to a problem and counts what the continuation asks of it.
class CountingProblem final : public cont::Problem {
 public:
  explicit CountingProblem(cont::Problem& p) : p_(p) {}
  int size() const override { return p_.size(); }
  bool residual(const cont::Vector& x, double p, cont::Vector& F) override {
    ++residuals;
    return p_.residual(x, p, F);
  }
  bool factorize(const cont::Vector& x, double p) override {
    ++factorizations;
    return p_.factorize(x, p);
  }
  bool solve(cont::Vector& b) override {
    ++solves;
    return p_.solve(b);
  }
  bool residual_p(const cont::Vector& x, double p, cont::Vector& out) override {
    return p_.residual_p(x, p, out);
  }
  double inner(const cont::Vector& a, const cont::Vector& b) const override {
    return p_.inner(a, b);
  }
  std::vector<std::string> monitor_names() const override { return p_.monitor_names(); }
  cont::Vector monitors(const cont::Vector& x, double p) override { return p_.monitors(x, p); }

  long residuals = 0, factorizations = 0, solves = 0;

 private:
  cont::Problem& p_;
};

void BM_SzeRoofPath(benchmark::State& st) {
  const double thickness = st.range(0) / 100.0;
  const bool snap_back = thickness < 10;  // case (d)
  for (auto _ : st) {
    st.PauseTiming();
    const verification::SzeRoof roof = verification::make_sze_roof(
        thickness, static_cast<int>(st.range(1)), static_cast<int>(st.range(2)));
    LoadProblem load(roof.mesh, roof.supports, *roof.element, roof.law, roof.loads, roof.options);
    CountingProblem problem(load);
    st.ResumeTiming();
    const cont::Branch b = cont::pseudo_arclength(problem, load.initial_point(), 0.0,
                                                  verification::sze_roof_settings(snap_back));
    st.PauseTiming();
    long iterations = 0;
    for (const cont::Point& p : b.points) iterations += p.newton_iterations;
    const double steps = static_cast<double>(b.points.size() - 1);
    st.counters["unknowns"] = load.size();
    st.counters["steps"] = steps;
    st.counters["failed_steps"] = b.failed_steps;
    st.counters["events"] = static_cast<double>(b.events.size());
    st.counters["newton_per_step"] = iterations / steps;
    st.counters["factorizations"] = static_cast<double>(problem.factorizations);
    st.counters["linear_solves"] = static_cast<double>(problem.solves);
    st.counters["residuals"] = static_cast<double>(problem.residuals);
    if (b.status != cont::Status::kReachedBound) st.SkipWithError(b.reason.c_str());
    st.ResumeTiming();
  }
}

}  // namespace
}  // namespace si

BENCHMARK(si::BM_SzeRoofPath)
    ->Args({1270, 8, 1})
    ->Args({635, 8, 1})
    ->Args({635, 24, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
