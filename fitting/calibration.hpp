// Calibration of an expensive model against a measured curve: find the parameters c within their
// bounds that minimise the weighted misfit
//   S(c) = sum_i w_i (y_model(x_i; c) - y_i)^2
// where each evaluation of y_model is a callback that may take seconds (a whole continuation
// run) and may fail; then report what the data say about c at the optimum. Generic: it knows
// parameters, bounds and a vector of predictions, nothing about shells (style.md, layering).
//
// Search (NLopt, on the parameters scaled by their bounds to v = (c - lower) / (upper - lower) in
// [0, 1], and on S / S(start)):
//  * kDerivativeFree (default): LN_BOBYQA (Powell 2009), a trust-region method on a quadratic
//    model interpolated through 2p + 1 points and updated with every evaluation. Chosen because
//    each evaluation costs a full run: BOBYQA reuses every one, needs no derivatives, so the
//    model's noise (adaptive steps, solver tolerances) is not differentiated, and it never leaves
//    the bounds. Initial trust radius 0.1 (a tenth of each range), stopped when the radius
//    falls below settings.xtol (1e-4 of each range) or S changes by less than ftol_rel.
//  * kGradient: LD_SLSQP with the gradient 2 J^T W r from forward differences of the model
//    (model_jacobian.hpp): p + 1 evaluations per gradient. Fewer iterations, more evaluations
//    each; useful with many parameters and a smooth model.
// An NLopt failure code (negative) is an error: the result's status is kFailed with NLopt's code
// and its best point, never quietly replaced by another method's answer. A model that fails
// during the search (a run that does not reach the last travel) counts as a bad point: NLopt sees
// twice the largest S met so far, and the failure is counted and reported.
//
// At the optimum (model_jacobian.hpp, fit_statistics.hpp, confidence_region.hpp,
// identifiability.hpp): the finite-difference Jacobian J of the model, the covariance
// C = s^2 (J^T W J)^-1 with s^2 = S / (n - p), standard errors, 95 % t intervals, the joint
// confidence ellipsoid, the correlation matrix, and identifiability warnings.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "fitting/confidence_region.hpp"
#include "fitting/identifiability.hpp"

namespace si::fit {

struct CalibrationParameter {
  std::string name;
  double lower = 0, upper = 0;  // finite, lower < upper
  double start = 0;             // lower <= start <= upper
};

// What the model returns for one parameter vector: a prediction per measured point, or a failure.
struct ModelOutput {
  Eigen::VectorXd predicted;
  bool ok = false;
  std::string failure;  // why not, when !ok
  std::string note;     // optional, for the progress report (e.g. how the run was started)
};
using CalibrationModel = std::function<ModelOutput(const Eigen::VectorXd& parameters)>;

struct CalibrationProblem {
  Eigen::VectorXd x, y;     // the measured curve (x is only reported; the model knows where)
  Eigen::VectorXd weights;  // empty: all 1; else w_i >= 0, finite, one per point
  std::vector<CalibrationParameter> parameters;
  CalibrationModel model;
};

enum class CalibrationAlgorithm { kDerivativeFree, kGradient };
// NLopt's name of the algorithm used: "LN_BOBYQA", "LD_SLSQP".
std::string calibration_algorithm_name(CalibrationAlgorithm algorithm);
enum class CalibrationPhase { kSearch, kJacobian };

// Reported after every model evaluation (one call at a time, also when evaluations run
// concurrently); the callback returns false to stop (Ctrl-C).
struct CalibrationProgress {
  int evaluation = 0;  // 1-based, all phases
  CalibrationPhase phase = CalibrationPhase::kSearch;
  Eigen::VectorXd parameters;
  bool ok = false;
  double sse = 0;       // S at this point (weighted); NaN if the model failed
  double best_sse = 0;  // the smallest S so far
  double seconds = 0;   // the evaluation's wall time
  std::string failure;
  std::string note;  // the model's ModelOutput::note
};

struct CalibrationSettings {
  CalibrationAlgorithm algorithm = CalibrationAlgorithm::kDerivativeFree;
  int max_evaluations = 100;    // model evaluations of the search (the Jacobian's 2p come on top)
  double initial_step = 0.1;    // BOBYQA's initial trust radius, as a fraction of each range
  double xtol = 1e-4;           // stop when the step is below this fraction of each range
  double ftol_rel = 1e-10;      // ... or S changes by less than this, relatively
  double jacobian_step = 1e-3;  // model_jacobian.hpp's relative_step
  // The Jacobian's 2p evaluations at the optimum run this many at a time (threads); the model
  // must then be thread-safe. The search itself is sequential.
  int concurrent_evaluations = 1;
  double confidence = 0.95;
  IdentifiabilityLimits limits;
  std::function<bool(const CalibrationProgress&)> progress;  // optional
};

enum class CalibrationStatus {
  kConverged,        // NLopt stopped on its tolerances; statistics computed
  kBudgetExhausted,  // NLopt stopped at max_evaluations; best point and statistics reported
  kInterrupted,      // the progress callback asked to stop; best point so far, no statistics
  kFailed,  // NLopt returned a failure code, the model failed at the start, or the Jacobian
            // could not be computed at the optimum
};

const char* to_string(CalibrationStatus status);  // "converged", "budget_exhausted", ...

struct CalibrationCounts {
  int search = 0;    // model evaluations by the search (the start included)
  int jacobian = 0;  // model evaluations for the Jacobian at the optimum
  int failed = 0;    // evaluations where the model failed (any phase)
  int total() const { return search + jacobian; }
};

struct CalibrationResult {
  CalibrationStatus status = CalibrationStatus::kFailed;
  std::string reason;
  std::string algorithm;  // "LN_BOBYQA" or "LD_SLSQP"
  int nlopt_code = 0;     // nlopt.h; negative: failure
  std::vector<std::string> names;
  Eigen::VectorXd start, parameters;  // parameters: the best point evaluated
  std::vector<bool> at_bound;         // within 1e-6 of the range from a bound
  double sse_start = 0;
  double sse = 0;  // weighted sum of squares at the optimum

  // At the optimum (when statistics_available):
  bool statistics_available = false;
  Eigen::VectorXd predicted, residuals;  // residual = predicted - measured
  int num_points = 0, dof = 0;
  double rmse = 0;              // sqrt(S / n) (weighted)
  double residual_std_dev = 0;  // s = sqrt(S / dof)
  Eigen::MatrixXd jacobian;     // d predicted / d c, finite differences
  Eigen::VectorXd jacobian_steps;
  Eigen::MatrixXd covariance, correlation;
  Eigen::VectorXd std_errors, ci_lower, ci_upper;
  // The Gauss-Newton step from the reported point (what the linearised problem says is left to
  // the optimum) and its largest component in standard errors: a check that the search went far
  // enough (<< 1), computed from the Jacobian above, not used to move the point.
  Eigen::VectorXd gauss_newton_step;
  double distance_to_optimum = 0;
  double confidence = 0.95;
  ConfidenceEllipsoid ellipsoid;
  IdentifiabilityReport identifiability;
  CalibrationCounts evaluations;
  double seconds = 0;
};

// Throws std::invalid_argument for an inconsistent problem (sizes, bounds, start outside its
// bounds, fewer than p + 2 points, bad weights). Numerical trouble is reported in the status.
CalibrationResult calibrate(const CalibrationProblem& problem, const CalibrationSettings& settings);

}  // namespace si::fit
