// The F distribution: the quantile that scales the joint confidence region of p parameters,
// {c : (c - c^)^T C^-1 (c - c^) <= p F(1 - alpha; p, n - p)} (Bates & Watts 1988, sec. 2.3;
// Seber & Wild 1989, sec. 5.2). Its distribution function is a regularized incomplete beta
// function, P(F <= x) = I_{d1 x / (d1 x + d2)}(d1/2, d2/2) (Abramowitz & Stegun 26.6.2), computed
// by student_t.hpp's incomplete_beta; the quantile by bracketing and bisection.
#pragma once

namespace si::fit {

// P(F <= x) for F with (d1, d2) > 0 degrees of freedom; 0 for x <= 0.
double fisher_f_cdf(double x, double d1, double d2);

// The p-quantile (0 < p < 1): fisher_f_cdf(fisher_f_quantile(p, d1, d2), d1, d2) = p.
double fisher_f_quantile(double p, double d1, double d2);

}  // namespace si::fit
