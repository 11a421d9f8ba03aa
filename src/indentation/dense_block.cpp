#include "indentation/dense_block.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace si {

SparseMatrix with_dense_block(const SparseMatrix& J, const std::vector<int>& indices) {
  SI_REQUIRE(J.isCompressed() && J.rows() == J.cols() &&
                 std::is_sorted(indices.begin(), indices.end()) &&
                 std::adjacent_find(indices.begin(), indices.end()) == indices.end() &&
                 (indices.empty() || (indices.front() >= 0 && indices.back() < J.rows())),
             "dense block: a square matrix, and indices ascending, distinct and inside it");
  const int n = static_cast<int>(J.cols());
  const int m = static_cast<int>(indices.size());
  std::vector<char> in_block(static_cast<std::size_t>(n), 0);
  for (int c : indices) in_block[static_cast<std::size_t>(c)] = 1;
  const int* outer = J.outerIndexPtr();
  const int* inner = J.innerIndexPtr();
  const double* value = J.valuePtr();
  // The columns' sizes first: a block column gains the block's rows it lacks.
  SparseMatrix out(n, n);
  int* starts = out.outerIndexPtr();
  starts[0] = 0;
  for (int c = 0; c < n; ++c) {
    int size = outer[c + 1] - outer[c];
    if (in_block[static_cast<std::size_t>(c)]) {
      size += m;
      for (int k = outer[c]; k < outer[c + 1]; ++k) size -= in_block[inner[k]];
    }
    starts[c + 1] = starts[c] + size;
  }
  out.resizeNonZeros(starts[n]);
  int* rows = out.innerIndexPtr();
  double* values = out.valuePtr();
  for (int c = 0; c < n; ++c) {
    int k = outer[c], at = starts[c];
    const int end = outer[c + 1];
    if (in_block[static_cast<std::size_t>(c)])
      for (int r : indices) {  // merge the column's rows with the block's
        for (; k < end && inner[k] < r; ++k, ++at) {
          rows[at] = inner[k];
          values[at] = value[k];
        }
        rows[at] = r;
        values[at++] = k < end && inner[k] == r ? value[k++] : 0.0;
      }
    for (; k < end; ++k, ++at) {
      rows[at] = inner[k];
      values[at] = value[k];
    }
  }
  return out;
}

std::vector<int> dense_block_slots(const SparseMatrix& J, const std::vector<int>& indices) {
  std::vector<int> slots;
  slots.reserve(indices.size());
  for (int c : indices) {
    const int* begin = J.innerIndexPtr() + J.outerIndexPtr()[c];
    const int* end = J.innerIndexPtr() + J.outerIndexPtr()[c + 1];
    const int* first = std::lower_bound(begin, end, indices.front());
    const bool contiguous = end - first >= static_cast<long>(indices.size()) &&
                            std::equal(indices.begin(), indices.end(), first);
    if (!contiguous)
      throw Error(ErrorKind::kInternal, "dense block: column " + std::to_string(c) +
                                            " does not hold the block's rows together");
    slots.push_back(static_cast<int>(first - J.innerIndexPtr()));
  }
  return slots;
}

}  // namespace si
