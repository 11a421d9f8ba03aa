// The contact rows' couplings kept beside J (row_coupling.hpp): the product and the assembled
// matrix against the same block written out densely.
#include "indentation/row_coupling.hpp"

#include <gtest/gtest.h>

#include <memory>

#include <Eigen/Dense>

namespace si {
namespace {

constexpr int kFirst = 5;  // shell rows before the contact rows
constexpr int kRows = 7;   // contact rows
constexpr int kSize = kFirst + kRows;

// Members 1, 2, 4, 6 of the contact rows; member 2 off the contact (b = 0).
RowCoupling make_coupling() {
  RowCoupling c;
  c.members = {1, 2, 4, 6};
  c.scale = Eigen::Vector4d(30.0, 0.0, 12.0, 45.0);
  // (q, p) = d layer_p / d lambda_q, mm/N; unsymmetric here, so that the two routes' reading of
  // the storage is checked (the elastic face's is symmetric).
  Eigen::Matrix4d C;
  C << 0.0, 0.4, 0.2, 0.3, 0.45, 0.0, 0.25, 0.2, 0.15, 0.35, 0.0, 0.1, 0.33, 0.21, 0.12, 0.0;
  c.coefficients = std::make_shared<Eigen::MatrixXd>(C * 1e-2);
  return c;
}

// The block as J's entries: row first + members[p], column first + members[q],
// b_p d layer_p / d lambda_q.
Eigen::MatrixXd dense_block(const RowCoupling& c) {
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(kSize, kSize);
  for (std::size_t p = 0; p < c.members.size(); ++p)
    for (std::size_t q = 0; q < c.members.size(); ++q)
      if (p != q)
        B(kFirst + c.members[p], kFirst + c.members[q]) =
            c.scale[static_cast<Eigen::Index>(p)] *
            (*c.coefficients)(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(p));
  return B;
}

SparseMatrix some_jacobian() {
  Eigen::MatrixXd J = Eigen::MatrixXd::Identity(kSize, kSize);
  J(0, kFirst + 1) = -0.5;  // a gradient in a member's column
  J(kFirst + 1, 0) = 2.0;
  J(kFirst + 4, kFirst + 6) = 0.75;  // an entry the block also writes: summed
  return J.sparseView();
}

TEST(RowCoupling, ProductIsTheBlocksAndSkipsTheOtherRows) {
  const RowCoupling c = make_coupling();
  const Eigen::VectorXd in = Eigen::VectorXd::LinSpaced(kSize, -1.0, 2.0);
  Eigen::VectorXd out = Eigen::VectorXd::Constant(kSize, 0.5);
  c.add_product(in, kFirst, out);
  const Eigen::VectorXd expected = Eigen::VectorXd::Constant(kSize, 0.5) + dense_block(c) * in;
  EXPECT_LT((out - expected).norm(), 1e-14 * expected.norm());
  EXPECT_EQ(out[kFirst + 2], 0.5);  // b = 0: reads nothing
}

TEST(RowCoupling, AddedToIsJPlusTheBlock) {
  const RowCoupling c = make_coupling();
  const SparseMatrix J = some_jacobian();
  const Eigen::MatrixXd expected = Eigen::MatrixXd(J) + dense_block(c);
  EXPECT_LT((Eigen::MatrixXd(c.added_to(J, kFirst)) - expected).norm(), 1e-14 * expected.norm());
}

TEST(RowCoupling, FewerThanTwoMembersCoupleNothing) {
  RowCoupling c = make_coupling();
  c.members = {3};
  c.scale = Eigen::VectorXd::Constant(1, 10.0);
  c.coefficients = std::make_shared<Eigen::MatrixXd>(Eigen::MatrixXd::Zero(1, 1));
  EXPECT_TRUE(c.empty());
  const SparseMatrix J = some_jacobian();
  EXPECT_EQ(c.added_to(J, kFirst).nonZeros(), J.nonZeros());
  Eigen::VectorXd out = Eigen::VectorXd::Zero(kSize);
  c.add_product(Eigen::VectorXd::Ones(kSize), kFirst, out);
  EXPECT_TRUE(out.isZero(0.0));
  EXPECT_TRUE(RowCoupling{}.empty());
}

}  // namespace
}  // namespace si
