// The source paper's cap as case-file text for the benchmarks: the [0/0]2S laminate of the paper's
// material, the clamped cap, an MITC4 mesh whose apex and edge sizes are the benchmark's first two
// arguments in 1/100 mm, refined within 13 mm; `mesh_keys` adds mesh keys (", symmetry: full")
// and `rest` the benchmark's own sections (kinematics, path, damage, ...). And the process CPU time
// of a path: the machines are shared, so CPU, not wall time, is what a ratio compares.
#pragma once

#include <benchmark/benchmark.h>
#include <time.h>

#include <string>

#include "analysis/indentation_run.hpp"

namespace si::bench {

inline std::string paper_cap_yaml(const benchmark::State& st, const std::string& mesh_keys,
                                  const std::string& rest) {
  return "material: paper-carbon-epoxy\n"
         "laminate: {layup: \"[0/0]2S\", ply_thickness: 0.475 mm}\n"
         "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
         "mesh: {element: mitc4, size_apex: " +
         std::to_string(st.range(0) / 100.0) +
         " mm, size_edge: " + std::to_string(st.range(1) / 100.0) + " mm, refine_radius: 13 mm" +
         mesh_keys + "}\n" + rest;
}

inline double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runs the path of `s` into `r`; returns its CPU seconds.
inline double cpu_seconds_of_path(IndentationSetup& s, PathResult& r) {
  const double start = cpu_seconds();
  r = run_indentation_path(s);
  return cpu_seconds() - start;
}

}  // namespace si::bench
