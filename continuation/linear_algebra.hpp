// The dense vector and matrix types of the continuation library.
#pragma once

#include <Eigen/Core>

namespace si::cont {

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

}  // namespace si::cont
