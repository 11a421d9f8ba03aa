// Choosing a polynomial's degree from the data: every degree from 0 up to a maximum is fitted
// (linear_fit.hpp) and scored by leave-one-out cross-validation and by Akaike's criterion; the
// scores of all degrees are returned with the one chosen, so the choice can be reported.
//
// Leave-one-out needs no refits: the residual of point i when it is left out is e_i / (1 - h_ii),
// h the hat matrix (the PRESS identity; Allen 1974), and LOOCV RMSE = sqrt(PRESS / n).
// AIC = n ln(SSE / n) + 2 k for k coefficients (Akaike 1974, Gaussian errors, constants dropped;
// counting the error variance as a parameter adds 2 to every degree and does not change the
// choice). AIC favours high degrees when n is small; AICc = AIC + 2 k (k + 1) / (n - k - 1)
// (Hurvich & Tsai 1989) corrects that and is infinite for k >= n - 1. Degrees with k >= n are not
// candidates: they interpolate, LOOCV is undefined (h_ii = 1) and AIC is -infinity.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace si::fit {

enum class DegreeCriterion { kLeaveOneOut, kAic, kAicc };

const char* to_string(DegreeCriterion criterion);

struct DegreeScore {
  int degree = 0;
  double sse = 0;
  double loocv_rmse = 0;
  double aic = 0;
  double aicc = 0;
};

struct DegreeSelection {
  DegreeCriterion criterion = DegreeCriterion::kLeaveOneOut;
  std::vector<DegreeScore> scores;  // degree 0, 1, ..., in order
  int chosen_degree = 0;            // the lowest degree with the best score
};

// Candidates 0..min(max_degree, n - 2). Throws std::invalid_argument for fewer than 2 points.
// Scores are floored at the roundoff level of the data, so that an exact polynomial does not
// pick a higher degree by rounding noise.
DegreeSelection select_polynomial_degree(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                         int max_degree, DegreeCriterion criterion);

}  // namespace si::fit
