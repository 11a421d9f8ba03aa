// Spectra's implicitly restarted Lanczos as the stability tools run it (lowest_eigenpairs.cpp:
// shift-invert on a factorization; penalized_stability.cpp: a projected penalised inverse): the
// basis size and one init() + compute() with EigenOptions.
#pragma once

#include <Spectra/Util/CompInfo.h>
#include <Spectra/Util/SelectionRule.h>

#include <algorithm>
#include <stdexcept>

#include "continuation/lowest_eigenpairs.hpp"

namespace si::cont {

// max(2k + 1, options.subspace) Lanczos vectors, at most the dimension of the space.
inline Eigen::Index lanczos_basis(Eigen::Index dimension, int k, const EigenOptions& options) {
  return std::min<Eigen::Index>(dimension, std::max(2 * k + 1, options.subspace));
}

// Starts from Spectra's own vector and iterates to options.tolerance; false if an operator's
// solve threw (std::runtime_error) or Spectra did not converge.
template <class Solver>
bool run_lanczos(Solver& solver, Spectra::SortRule selection, Spectra::SortRule sorting,
                 const EigenOptions& options) {
  solver.init();
  try {
    solver.compute(selection, options.max_iterations, options.tolerance, sorting);
  } catch (const std::runtime_error&) {
    return false;
  }
  return solver.info() == Spectra::CompInfo::Successful;
}

}  // namespace si::cont
