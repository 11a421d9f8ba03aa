#include "indentation/contact_term.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace si {

int value_slot(const SparseMatrix& J, int row, int col) {
  const int* begin = J.innerIndexPtr() + J.outerIndexPtr()[col];
  const int* end = J.innerIndexPtr() + J.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  SI_REQUIRE(it != end && *it == row, "indentation Jacobian: entry missing from the pattern");
  return static_cast<int>(it - J.innerIndexPtr());
}

}  // namespace si
