// A dense block added to a compressed sparse pattern: rows and columns `indices` (ascending),
// each row with an entry in every one of the columns: the contact rows' couplings (an elastic
// face's zone, row_coupling.hpp) assembled into J for a sparse LU. Laid column by column in one
// pass, not as triplets (up to kMaxZoneNodes^2 = 9e6 entries), and its values found by column
// rather than entry by entry.
#pragma once

#include <vector>

#include "core/sparse.hpp"

namespace si {

// J with the entries indices x indices added to its pattern (value 0 where J had none).
SparseMatrix with_dense_block(const SparseMatrix& J, const std::vector<int>& indices);

// Per column indices[k] of J: the value slot of its entry in row indices[0]; the block's other
// rows follow it in order. Throws an internal error if J lacks an entry of the block or has one
// between them.
std::vector<int> dense_block_slots(const SparseMatrix& J, const std::vector<int>& indices);

}  // namespace si
