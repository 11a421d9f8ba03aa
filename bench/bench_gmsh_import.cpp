// Import of a Gmsh mesh of ~1e5 quadrangles (issue 17 target: under 2 s). The file is generated
// here, in the temporary directory, and never committed: a 316 x 316 plate (99 856 elements,
// 100 489 nodes) in MSH 4.1 text with its four sides as physical curves; the benchmark reads it
// with read_gmsh_mesh (parse, topology and orientation checks, directors, check_mesh).
// Run: cmake -S . -B build -G Ninja -DSHELLINDENT_BENCH=ON && cmake --build build --target
// bench_gmsh_import && build/bench/bench_gmsh_import
#include <benchmark/benchmark.h>

#include <filesystem>

#include "model/gmsh_reader.hpp"
#include "model/plate_meshes.hpp"
#include "msh_test_writer.hpp"

namespace si {
namespace {

std::string generated_file(int n) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("shellindent_bench_plate_" + std::to_string(n) + ".msh");
  if (!std::filesystem::exists(path)) {
    const Mesh mesh = rectangular_plate_mesh(1000, 1000, n, n);
    testing::write_msh41(mesh, {"edge_x0", "edge_x1", "edge_y0", "edge_y1"}, path.string());
  }
  return path.string();
}

void BM_GmshImport(benchmark::State& st) {
  const std::string path = generated_file(static_cast<int>(st.range(0)));
  int elements = 0;
  for (auto _ : st) {
    const ImportedMesh m = read_gmsh_mesh(path);
    elements = m.mesh.num_elements();
    benchmark::DoNotOptimize(m.mesh.nodes.data());
  }
  st.counters["elements"] = elements;
  st.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
}
BENCHMARK(BM_GmshImport)->Arg(100)->Arg(316)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace si
