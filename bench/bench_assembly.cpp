// Timing of the model layer on structured square plates of ~1e3, 1e4, 1e5 dofs (clamped on one
// edge) with the fake spring-net element: pattern build, assembly (1 and 2 threads; and with a
// trivial element, i.e. the scatter alone), CHOLMOD analysis and factorization, and the target
// operation one assembly + one factorization.
// Run: cmake -S . -B build -G Ninja -DSHELLINDENT_BENCH=ON && cmake --build build --target
// bench_assembly && build/bench/bench_assembly
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "model/assembler.hpp"
#include "model/supports.hpp"
#include "solvers/linear_solver.hpp"
#include "spring_net_element.hpp"
#include "test_meshes.hpp"

namespace si {
namespace {

// An element that only copies a fixed response: assembly time with it is the scatter cost.
class ConstantElement : public ShellElement {
 public:
  ConstantElement() {
    response_.force.setOnes();
    response_.tangent.setIdentity();
    response_.energy = 1;
  }
  std::string name() const override { return "constant"; }
  void compute(const ElementGeometry&, const std::array<NodeState, 4>&, const ShellLaw&, Kinematics,
               const ElementRequest&, ElementResponse& out) const override {
    out = response_;
  }
  ElementStrains strains_at_nodes(const ElementGeometry&, const std::array<NodeState, 4>&,
                                  Kinematics) const override {
    return {};
  }

 private:
  ElementResponse response_;
};

struct Problem {
  explicit Problem(int n)
      : mesh(testing::square_plate(n, n, 100.0, 100.0)),
        dofs(make_dof_map(mesh, {{SupportKind::kClamped, "left", -1, {}}})),
        state(reference_state(mesh)) {
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const Vector3d& X = mesh.nodes[i];
      state[i].u = Vector3d(1e-3 * X.y(), 0, 0.5 * std::sin(0.05 * X.x()));
      rotate_node(state[i], 0.01, -0.02);
    }
  }
  Mesh mesh;
  DofMap dofs;
  std::vector<NodeState> state;
  testing::SpringNetElement element;
};

// Plate sizes n with 5 (n+1)^2 - clamped ~ 1e3, 1e4, 1e5 dofs.
void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {13, 44, 141}) b->Arg(n);
}
void sizes_threads(benchmark::internal::Benchmark* b) {
  for (int n : {13, 44, 141})
    for (int t : {1, 2}) b->Args({n, t});
}

void BM_PatternBuild(benchmark::State& st) {
  const Problem p(static_cast<int>(st.range(0)));
  for (auto _ : st) {
    Assembler a(p.mesh, p.dofs, p.element, testing::unused_law(), Kinematics::kNonlinear);
    benchmark::DoNotOptimize(a);
  }
  st.counters["dofs"] = p.dofs.num_free();
}

void BM_Assembly(benchmark::State& st) {
  const Problem p(static_cast<int>(st.range(0)));
  const Assembler a(p.mesh, p.dofs, p.element, testing::unused_law(), Kinematics::kNonlinear,
                    static_cast<int>(st.range(1)));
  Assembly out = a.make_assembly();
  for (auto _ : st) a.assemble(p.state, {}, out);
  st.counters["dofs"] = p.dofs.num_free();
  st.counters["nnz"] = static_cast<double>(out.tangent.nonZeros());
}

void BM_ScatterOnly(benchmark::State& st) {
  const Problem p(static_cast<int>(st.range(0)));
  const ConstantElement constant;
  const Assembler a(p.mesh, p.dofs, constant, testing::unused_law(), Kinematics::kNonlinear,
                    static_cast<int>(st.range(1)));
  Assembly out = a.make_assembly();
  for (auto _ : st) a.assemble(p.state, {}, out);
  st.counters["dofs"] = p.dofs.num_free();
}

void BM_CholmodAnalyze(benchmark::State& st) {
  const Problem p(static_cast<int>(st.range(0)));
  const Assembler a(p.mesh, p.dofs, p.element, testing::unused_law(), Kinematics::kNonlinear);
  Assembly out = a.make_assembly();
  a.assemble(p.state, {}, out);
  for (auto _ : st) {
    auto solver = make_linear_solver(LinearSolverKind::kCholmod);
    solver->analyze(out.tangent);
  }
  st.counters["dofs"] = p.dofs.num_free();
}

void BM_CholmodFactorize(benchmark::State& st) {
  const Problem p(static_cast<int>(st.range(0)));
  const Assembler a(p.mesh, p.dofs, p.element, testing::unused_law(), Kinematics::kNonlinear);
  Assembly out = a.make_assembly();
  a.assemble(p.state, {}, out);
  auto solver = make_linear_solver(st.range(1) == 0 ? LinearSolverKind::kCholmod
                                                    : LinearSolverKind::kUmfpack);
  solver->analyze(out.tangent);
  for (auto _ : st) solver->factorize(out.tangent);
  st.SetLabel(solver->name());
  st.counters["dofs"] = p.dofs.num_free();
}

// The target: one assembly + one (re)factorization, symbolic analysis done beforehand.
void BM_AssemblyPlusFactorize(benchmark::State& st) {
  const Problem p(static_cast<int>(st.range(0)));
  const Assembler a(p.mesh, p.dofs, p.element, testing::unused_law(), Kinematics::kNonlinear);
  Assembly out = a.make_assembly();
  a.assemble(p.state, {}, out);
  auto solver = make_linear_solver(LinearSolverKind::kCholmod);
  solver->analyze(out.tangent);
  for (auto _ : st) {
    a.assemble(p.state, {}, out);
    solver->factorize(out.tangent);
  }
  st.counters["dofs"] = p.dofs.num_free();
}

BENCHMARK(BM_PatternBuild)->Apply(sizes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Assembly)->Apply(sizes_threads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ScatterOnly)->Apply(sizes_threads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CholmodAnalyze)->Apply(sizes)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CholmodFactorize)
    ->ArgsProduct({{13, 44, 141}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_AssemblyPlusFactorize)->Apply(sizes)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace si
