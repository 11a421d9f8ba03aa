// Student's t distribution: the quantiles that turn standard errors into confidence intervals.
// Computed from the regularized incomplete beta function (Abramowitz & Stegun 26.5.8 and 26.7.1:
// P(|T| <= t) = 1 - I_{v/(v+t^2)}(v/2, 1/2)), evaluated by its continued fraction
// (A&S 26.5.8) with the modified Lentz method; the quantile is found by safeguarded bisection.
#pragma once

namespace si::fit {

// Regularized incomplete beta function I_x(a, b) for a, b > 0 and 0 <= x <= 1 (to ~1e-14).
double incomplete_beta(double a, double b, double x);

// P(T <= t) for T with `dof` > 0 degrees of freedom (dof need not be an integer).
double student_t_cdf(double t, double dof);

// The p-quantile of T (0 < p < 1): student_t_cdf(student_t_quantile(p, v), v) = p.
// Two-sided 95 % intervals use p = 0.975.
double student_t_quantile(double p, double dof);

}  // namespace si::fit
