// The sparse matrix type of the stability tools (inertia.hpp, lowest_eigenpairs.hpp,
// constraint_null_space.hpp): Eigen's compressed column storage with int indices, the type the
// shell toolkit assembles, so its matrices are passed without a copy.
#pragma once

#include <Eigen/SparseCore>

#include "continuation/linear_algebra.hpp"

namespace si::cont {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace si::cont
