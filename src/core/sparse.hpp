// The sparse matrix type of the assembled tangents and Jacobians: CSC, full storage (not a
// triangle), int indices (model/assembler.hpp; the solvers of src/solvers/ factor it).
#pragma once

#include <Eigen/SparseCore>

namespace si {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace si
