// NIST StRD linear regression problems that are polynomials
// (https://www.itl.nist.gov/div898/strd/lls/lls.shtml), fitted by fit_polynomial (QR). NIST
// certifies 15 digits; a double-precision QR of these ill-conditioned Vandermonde matrices is
// expected to give (McCullough 1999's scoring) at least: Pontius (lower difficulty) 9 digits,
// Wampler1 and Wampler4 (higher difficulty, condition number ~ 5e15 for raw monomials) 6 digits,
// which is the acceptance level of issue 6 for the nonlinear problems.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../verification_record.hpp"
#include "fitting/linear_fit.hpp"
#include "fitting_test_support.hpp"

namespace si::fit {
namespace {

using testing::agreeing_digits;
using testing::read_strd;

void expect_certified(const std::string& file, double digits) {
  const auto p = read_strd(file);
  const int degree = static_cast<int>(p.certified.size()) - 1;
  const FitResult r = fit_polynomial(p.x, p.y, degree);
  ASSERT_EQ(r.status, FitStatus::kConverged) << r.reason;
  for (int j = 0; j <= degree; ++j) {
    EXPECT_GE(agreeing_digits(r.parameters[j], p.certified[j]), digits)
        << file << " B" << j << " = " << r.parameters[j];
    // Relative error <= 10^-digits is "digits agreeing digits" (certified B_j are non-zero).
    si::test::record_verification("nist-strd", file + " B" + std::to_string(j), p.certified[j],
                                  r.parameters[j], std::pow(10.0, -digits),
                                  "NIST StRD certified values (15 digits)");
    if (p.certified_sd[j] != 0.0) {
      EXPECT_GE(agreeing_digits(r.std_errors[j], p.certified_sd[j]), digits)
          << file << " sd(B" << j << ") = " << r.std_errors[j];
    }
  }
  if (p.stats.at("rsd") != 0.0) {
    EXPECT_GE(agreeing_digits(r.residual_std_dev, p.stats.at("rsd")), digits) << file;
  }
  EXPECT_GE(agreeing_digits(r.r_squared, p.stats.at("r2")), digits) << file;
}

TEST(NistLinear, Pontius_Quadratic) {
  expect_certified("pontius.txt", 9.0);
}
TEST(NistLinear, Wampler1_ExactQuintic) {
  expect_certified("wampler1.txt", 6.0);
}
TEST(NistLinear, Wampler4_NoisyQuintic) {
  expect_certified("wampler4.txt", 6.0);
}

}  // namespace
}  // namespace si::fit
