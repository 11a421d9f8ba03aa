// Contact rows that read each other's multipliers, kept beside the Jacobian's sparse pattern
// rather than in it: the elastic face's zone (elastic_face.hpp), where row i of the contact rows
// has b_i C_ij in multiplier j's column for every pair of zone members i != j (b_i = d_b kappa
// of row i, C the face's influence coefficients, mm/N). The block is dense over the zone while
// only the pressed rows have b != 0: in J it was most of J's entries on a fine mesh (3.4e6 of
// 4.3e6 on the 0.25 mm quarter cap at 10 mm, a zone of 1,858 nodes around ~550 pressed ones),
// zeros over the unpressed rows in every GMRES product and assembly. Here a product costs the
// pressed rows times the zone, and C is gathered once per pattern. The LU routes assemble it
// (added_to()).
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "core/sparse.hpp"

namespace si {

struct RowCoupling {
  // The coupled rows, as indices among the contact rows (ascending).
  std::vector<int> members;
  // b per member (N/mm; 0 for a row off the contact, which then reads nothing).
  Eigen::VectorXd scale;
  // C over the members, mm/N, stored by rows: column p holds what member p's row reads,
  // (q, p) = d layer_p / d lambda_q, so that a product reads contiguous memory; zero diagonal (a
  // row's own coefficient lies in its diagonal a). Shared by the factorizations of one pattern.
  std::shared_ptr<const Eigen::MatrixXd> coefficients;

  bool empty() const { return members.size() < 2; }
  // The entry of contact row members[p] in the column of members[q].
  double entry(int p, int q) const { return scale[p] * (*coefficients)(q, p); }
  // out += (the block) in, over the contact rows that start at `first` in both vectors.
  void add_product(const Eigen::VectorXd& in, int first, Eigen::VectorXd& out) const;
  // J (the contact rows from `first`) with the block's entries added to its pattern and values,
  // for a sparse LU.
  SparseMatrix added_to(const SparseMatrix& J, int first) const;
};

}  // namespace si
