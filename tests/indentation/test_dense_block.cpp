// The dense block laid into a compressed pattern (dense_block.hpp) against the same entries laid
// as triplets, and its value slots against a search entry by entry.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/error.hpp"
#include "indentation/contact_term.hpp"
#include "indentation/dense_block.hpp"

namespace si {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

// A random sparse pattern with distinct values (so that a misplaced value shows).
Triplets random_entries(int n, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  Triplets t;
  for (int k = 0; k < count; ++k) t.emplace_back(pick(rng), pick(rng), 1.0 + k);
  return t;
}

SparseMatrix from(const Triplets& t, int n) {
  SparseMatrix J(n, n);
  J.setFromTriplets(t.begin(), t.end());
  J.makeCompressed();
  return J;
}

TEST(DenseBlock, PatternIsTheTripletsUnionAndValuesStay) {
  const int n = 40;
  const Triplets base = random_entries(n, 150, 7);
  const std::vector<int> block = {3, 4, 9, 17, 18, 30, 39};
  Triplets with = base;
  for (int r : block)
    for (int c : block) with.emplace_back(r, c, 0.0);
  const SparseMatrix expected = from(with, n);
  const SparseMatrix merged = with_dense_block(from(base, n), block);
  ASSERT_EQ(merged.nonZeros(), expected.nonZeros());
  for (int c = 0; c <= n; ++c) EXPECT_EQ(merged.outerIndexPtr()[c], expected.outerIndexPtr()[c]);
  for (int k = 0; k < expected.nonZeros(); ++k) {
    EXPECT_EQ(merged.innerIndexPtr()[k], expected.innerIndexPtr()[k]);
    EXPECT_EQ(merged.valuePtr()[k], expected.valuePtr()[k]);  // sums of the duplicates, or 0
  }
}

TEST(DenseBlock, SlotsAreTheBlockRunsOfEachColumn) {
  const int n = 30;
  // Entries outside the block's rows only in its columns (as the shell's rows above the
  // contact rows), and some inside it.
  Triplets t = {{0, 12, 1.0}, {2, 20, 2.0}, {12, 12, 3.0}, {25, 25, 4.0}, {29, 20, 5.0}};
  const std::vector<int> block = {12, 15, 20, 25};
  const SparseMatrix J = with_dense_block(from(t, n), block);
  const std::vector<int> slots = dense_block_slots(J, block);
  ASSERT_EQ(slots.size(), block.size());
  for (std::size_t k = 0; k < block.size(); ++k)
    for (std::size_t q = 0; q < block.size(); ++q)
      EXPECT_EQ(slots[k] + static_cast<int>(q), value_slot(J, block[q], block[k]));
}

TEST(DenseBlock, AnEntryAmongTheBlockRowsIsRefused) {
  const int n = 10;
  const std::vector<int> block = {2, 6};
  // Row 4 lies between the block's rows in column 6: the run is broken.
  const SparseMatrix J = with_dense_block(from({{4, 6, 1.0}}, n), block);
  EXPECT_THROW(dense_block_slots(J, block), Error);
  EXPECT_NO_THROW(dense_block_slots(with_dense_block(from({{8, 6, 1.0}}, n), block), block));
}

TEST(DenseBlock, UnsortedOrOutsideIndicesAreRefused) {
  const SparseMatrix J = from({{0, 0, 1.0}}, 5);
  EXPECT_THROW(with_dense_block(J, {3, 1}), Error);
  EXPECT_THROW(with_dense_block(J, {1, 1}), Error);
  EXPECT_THROW(with_dense_block(J, {1, 5}), Error);
  EXPECT_THROW(with_dense_block(SparseMatrix(4, 5), {1}), Error);
  EXPECT_EQ(with_dense_block(J, {}).nonZeros(), 1);
}

}  // namespace
}  // namespace si
