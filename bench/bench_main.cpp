// The benchmarks' main(): OpenBLAS single-threaded as in the CLI (core/blas_threads.hpp), so that
// the figures are those of a run.
#include <benchmark/benchmark.h>

#include "core/blas_threads.hpp"

int main(int argc, char** argv) {
  si::limit_blas_threads();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
