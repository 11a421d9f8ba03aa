// Cost of one section analysis (vam.md section 13: "microseconds to milliseconds per lay-up").
// A lay-up sweep calls it once per lay-up, the shell solver once per section.
#include <benchmark/benchmark.h>

#include "material/material_library.hpp"
#include "section/clt_section.hpp"
#include "section/layup_notation.hpp"
#include "section/vam_section.hpp"

namespace {

si::Laminate paper_laminate(const char* notation) {
  const si::Material m = si::library_material("paper-carbon-epoxy");
  si::Laminate lam;
  for (double a : si::parse_layup(notation)) lam.plies.push_back(si::Ply{m, 0.475, a});
  return lam;
}

void BM_Vam_45_2S(benchmark::State& state) {
  const si::Laminate lam = paper_laminate("[45/-45]2S");
  const si::VamOptions options{static_cast<int>(state.range(0)), 1};
  for (auto _ : state) benchmark::DoNotOptimize(si::analyze_vam(lam, options));
}
BENCHMARK(BM_Vam_45_2S)->Arg(3)->Arg(4)->Unit(benchmark::kMicrosecond);

void BM_Vam_32Plies(benchmark::State& state) {
  const si::Laminate lam = paper_laminate("[0/45/-45/90]4S");
  for (auto _ : state) benchmark::DoNotOptimize(si::analyze_vam(lam));
}
BENCHMARK(BM_Vam_32Plies)->Unit(benchmark::kMicrosecond);

void BM_Clt_45_2S(benchmark::State& state) {
  const si::Laminate lam = paper_laminate("[45/-45]2S");
  for (auto _ : state) benchmark::DoNotOptimize(si::clt_abd(lam));
}
BENCHMARK(BM_Clt_45_2S)->Unit(benchmark::kMicrosecond);

}  // namespace
