#include "continuation/stability_analysis.hpp"

#include "continuation/constraint_null_space.hpp"

namespace si::cont {

bool analyse_stability(const SparseMatrix& K, const SparseMatrix& A, int modes, Stability& out,
                       const StabilityOptions& options) {
  const bool constrained = A.rows() > 0;
  NullSpaceBasis basis;
  if (constrained) basis = constraint_null_space(A, options.rank_tolerance);
  const SparseMatrix reduced = constrained ? restrict_to_null_space(K, basis.Z) : SparseMatrix();
  const SparseMatrix& tangent = constrained ? reduced : K;

  const double tol = options.zero_pivot_tolerance;
  const FactorizationFactory make =
      options.factorization
          ? options.factorization
          : FactorizationFactory([tol] { return std::make_unique<SparseLdlt>(tol); });
  const std::unique_ptr<SymmetricFactorization> factorization = make();
  if (!factorization->factorize(tangent, 0.0)) return false;
  out.negative = factorization->inertia().negative;
  out.zero = factorization->inertia().zero;
  Eigenpairs pairs;
  if (!lowest_eigenpairs(tangent, modes, *factorization, options.eigen, pairs, make)) return false;
  out.eigenvalues = pairs.values;
  out.modes.clear();
  for (Eigen::Index c = 0; c < pairs.vectors.cols(); ++c)
    out.modes.push_back(constrained ? Vector(basis.Z * pairs.vectors.col(c))
                                    : Vector(pairs.vectors.col(c)));
  return true;
}

Vector multiplier_direction(const SparseMatrix& K, const SparseMatrix& A, const Vector& v) {
  return multiplier_direction_from_product(A, K * v);
}

Vector multiplier_direction_from_product(const SparseMatrix& A, const Vector& Kv) {
  const SparseMatrix AAt = A * SparseMatrix(A.transpose());
  Eigen::SimplicialLDLT<SparseMatrix> gram(AAt);
  const Vector rhs = -(A * Kv);
  return gram.solve(rhs);
}

}  // namespace si::cont
