// Can the data separate the parameters? Judged at the estimate from the Jacobian J of the model
// (weighted, W^1/2 J) with its columns scaled to unit length, which makes the judgement
// independent of the parameters' units (Belsley, Kuh & Welsch 1980, "Regression Diagnostics",
// ch. 3: the condition indices sigma_max / sigma_k of the column-equilibrated matrix, and the
// right singular vectors of the small sigma_k that show which parameters are involved), and
// from the correlation matrix of the estimates (Bates & Watts 1988, sec. 2.3; Seber & Wild 1989,
// sec. 3.4: |correlation| near 1 means the data fix a combination, not each parameter).
//
// Warnings:
//   insensitive      the model does not depend on a parameter (zero or non-finite column);
//   ill-conditioned  cond(J_s^T J_s) = (sigma_max / sigma_min)^2 above the limit (default 1e3,
//                    a condition index of ~32: Belsley et al.'s "strong" dependency starts at 30);
//   correlated       |correlation| of two estimates above the limit (default 0.99);
//   null direction   a right singular vector of J_s whose singular value is below
//                    sigma_max / sqrt(condition limit): moving the parameters along it barely
//                    changes the fit; the parameters carrying 95 % of it are named.
// Enums here; the words come from describe(), for reports.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace si::fit {

enum class IdentifiabilityIssue { kInsensitive, kIllConditioned, kCorrelated, kNullDirection };

const char* to_string(IdentifiabilityIssue issue);  // "insensitive", "ill_conditioned", ...

struct IdentifiabilityWarning {
  IdentifiabilityIssue issue = IdentifiabilityIssue::kIllConditioned;
  std::vector<int> parameters;  // indices of the parameters involved
  double value = 0;             // condition number, correlation, or sigma_k / sigma_max
  Eigen::VectorXd direction;    // kNullDirection: the singular vector (scaled parameters)
};

struct IdentifiabilityLimits {
  double condition = 1e3;     // of the scaled J^T J
  double correlation = 0.99;  // |correlation| of two estimates
};

struct IdentifiabilityReport {
  double condition_number = 0;       // cond(J_s^T J_s); infinite if J_s is singular
  Eigen::VectorXd singular_values;   // of J_s, descending
  Eigen::MatrixXd singular_vectors;  // right singular vectors of J_s, as columns
  std::vector<IdentifiabilityWarning> warnings;
  bool identifiable() const { return warnings.empty(); }
};

// weighted_jacobian: W^1/2 J (n x p); correlation: p x p (NaN entries are skipped).
IdentifiabilityReport assess_identifiability(const Eigen::MatrixXd& weighted_jacobian,
                                             const Eigen::MatrixXd& correlation,
                                             const IdentifiabilityLimits& limits = {});

// One line in words, naming the parameters: "indenter.material.E and indenter.material.nu are
// correlated (r = -0.9999): the data fix a combination of them, not each".
std::string describe(const IdentifiabilityWarning& warning, const std::vector<std::string>& names);

}  // namespace si::fit
