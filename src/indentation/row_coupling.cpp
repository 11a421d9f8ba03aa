#include "indentation/row_coupling.hpp"

#include "core/error.hpp"
#include "indentation/dense_block.hpp"

namespace si {

void RowCoupling::add_product(const Eigen::VectorXd& in, int first, Eigen::VectorXd& out) const {
  if (empty()) return;
  const int m = static_cast<int>(members.size());
  Eigen::VectorXd x(m);
  for (int q = 0; q < m; ++q) x[q] = in[first + members[q]];
  for (int p = 0; p < m; ++p)
    if (scale[p] != 0.0) out[first + members[p]] += scale[p] * coefficients->col(p).dot(x);
}

SparseMatrix RowCoupling::added_to(const SparseMatrix& J, int first) const {
  if (empty()) return J;
  std::vector<int> block(members);
  for (int& i : block) i += first;
  SparseMatrix out = with_dense_block(J, block);
  const std::vector<int> slots = dense_block_slots(out, block);
  const int m = static_cast<int>(members.size());
  for (int q = 0; q < m; ++q)
    for (int p = 0; p < m; ++p)
      if (p != q) out.valuePtr()[slots[q] + p] += entry(p, q);
  return out;
}

}  // namespace si
