// exp(A) of a small dense (complex) matrix: scaling and squaring with a truncated Taylor series
// (Moler & Van Loan, "Nineteen dubious ways to compute the exponential of a matrix, twenty-five
// years later", SIAM Review 45 (2003) 3-49, methods 1 and 3). A is scaled by 2^-s until its
// 1-norm is at most 1/2, where 18 Taylor terms leave a truncation error below 1e-22 relative,
// then squared s times. Meant for the 6 x 6 and 9 x 9 transfer matrices of a layered elastic
// medium over one step of at most about one wavelength (contact/layer_compliance.hpp), whose
// exponentials grow by a few hundred at most: the squarings then lose no more than a few digits.
// Not a general purpose routine for stiff or large matrices (no Pade, no balancing). A template
// so that fixed-size matrices stay on the stack.
#pragma once

#include <cmath>

#include <Eigen/Dense>

namespace si {

template <class Matrix>
Matrix matrix_exponential(const Matrix& A) {
  const double norm = A.cwiseAbs().colwise().sum().maxCoeff();
  const int squarings = norm > 0.5 ? static_cast<int>(std::ceil(std::log2(norm / 0.5))) : 0;
  const Matrix B = A / std::ldexp(1.0, squarings);
  constexpr int kTerms = 18;  // ||B|| <= 1/2: 0.5^19 / 19! < 1e-22
  Matrix term = Matrix::Identity(A.rows(), A.cols());
  Matrix sum = term;
  for (int k = 1; k <= kTerms; ++k) {
    term = (term * B / static_cast<double>(k)).eval();
    sum += term;
  }
  for (int k = 0; k < squarings; ++k) sum = (sum * sum).eval();
  return sum;
}

}  // namespace si
