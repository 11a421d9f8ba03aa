#include "fitting/calibration.hpp"

#include <nlopt.hpp>

#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

#include "fitting/fit_result.hpp"
#include "fitting/fit_statistics.hpp"
#include "fitting/model_jacobian.hpp"
#include "fitting/nlopt_status.hpp"

namespace si::fit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using Clock = std::chrono::steady_clock;

struct Interrupted {};  // the progress callback asked to stop

void check_problem(const CalibrationProblem& p, const CalibrationSettings& s) {
  const auto n = p.y.size();
  const auto np = static_cast<Eigen::Index>(p.parameters.size());
  if (np < 1) throw std::invalid_argument("calibration: no parameters");
  if (!p.model) throw std::invalid_argument("calibration: no model");
  if (p.x.size() != n) throw std::invalid_argument("calibration: x and y differ in length");
  if (n < np + 2)
    throw std::invalid_argument("calibration: " + std::to_string(np) +
                                " parameter(s) need at least " + std::to_string(np + 2) +
                                " points, got " + std::to_string(n));
  if (!p.y.allFinite()) throw std::invalid_argument("calibration: measured values not finite");
  if (p.weights.size() != 0 &&
      (p.weights.size() != n || !p.weights.allFinite() || p.weights.minCoeff() < 0.0))
    throw std::invalid_argument("calibration: weights must be finite, >= 0, one per point");
  for (const CalibrationParameter& c : p.parameters) {
    if (!(std::isfinite(c.lower) && std::isfinite(c.upper) && c.lower < c.upper))
      throw std::invalid_argument("calibration: " + c.name + ": needs finite bounds lower < upper");
    if (!(c.lower <= c.start && c.start <= c.upper))
      throw std::invalid_argument("calibration: " + c.name + ": the start is outside its bounds");
  }
  if (!(s.confidence > 0.0 && s.confidence < 1.0))
    throw std::invalid_argument("calibration: confidence must be in (0, 1)");
  if (s.max_evaluations < 2 * np + 2)
    throw std::invalid_argument("calibration: max_evaluations must be at least 2p + 2");
}

// Every model evaluation goes through here: timed, counted, reported, remembered (an exact
// repeat - NLopt's first call at the start - is not run again), the best one kept.
class Evaluations {
 public:
  struct Record {
    Eigen::VectorXd c;
    ModelOutput out;
    double sse = kNaN;
  };

  Evaluations(const CalibrationProblem& p, const CalibrationSettings& s, CalibrationCounts& counts)
      : p_(p), s_(s), counts_(counts) {}

  // A copy: the records grow while a caller still looks at an earlier one. Thread-safe: the
  // model runs outside the lock, the bookkeeping and the progress report inside it.
  Record run(const Eigen::VectorXd& c, CalibrationPhase phase) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      for (const Record& r : done_)
        if (r.c == c) return r;
    }
    const auto t0 = Clock::now();
    Record r{c, p_.model(c), kNaN};
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    r.out.ok = r.out.ok && r.out.predicted.size() == p_.y.size() && r.out.predicted.allFinite();
    if (r.out.ok) r.sse = weighted_sse(r.out.predicted);
    const std::lock_guard<std::mutex> lock(mutex_);
    if (r.out.ok && r.sse < best_sse()) best_ = static_cast<int>(done_.size());
    if (r.out.ok) worst_ = std::max(worst_, r.sse);
    (phase == CalibrationPhase::kSearch ? counts_.search : counts_.jacobian) += 1;
    counts_.failed += r.out.ok ? 0 : 1;
    done_.push_back(r);
    if (s_.progress) {
      CalibrationProgress info{counts_.total(), phase,     c, r.out.ok, r.sse, best_sse(), seconds,
                               r.out.failure,   r.out.note};
      if (!s_.progress(info)) throw Interrupted{};
    }
    return r;
  }

  double weighted_sse(const Eigen::VectorXd& predicted) const {
    const Eigen::ArrayXd r2 = (predicted - p_.y).array().square();
    return p_.weights.size() ? (p_.weights.array() * r2).sum() : r2.sum();
  }
  double best_sse() const { return best_ >= 0 ? done_[best_].sse : kInf; }
  const Record* best() const { return best_ >= 0 ? &done_[best_] : nullptr; }
  double worst_sse() const { return worst_; }

 private:
  const CalibrationProblem& p_;
  const CalibrationSettings& s_;
  CalibrationCounts& counts_;
  std::vector<Record> done_;
  std::mutex mutex_;
  int best_ = -1;
  double worst_ = 0.0;
};

// What the NLopt objective sees: v in [0, 1]^p, c = lower + v * width, f = S(c) / S(start).
struct Search {
  Evaluations* ev = nullptr;
  const CalibrationProblem* problem = nullptr;
  const CalibrationSettings* settings = nullptr;
  Eigen::VectorXd lower, upper, width;
  double normalization = 1.0;
  bool interrupted = false;

  Eigen::VectorXd parameters(const std::vector<double>& v) const {
    return lower + width.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()));
  }
};

double search_objective(const std::vector<double>& v, std::vector<double>& grad, void* data) {
  auto& s = *static_cast<Search*>(data);
  try {
    const Eigen::VectorXd c = s.parameters(v).cwiseMax(s.lower).cwiseMin(s.upper);
    const Evaluations::Record r = s.ev->run(c, CalibrationPhase::kSearch);
    // A failed run: worse than anything met so far, so that the search turns away from it.
    const double sse = r.out.ok ? r.sse : 2.0 * s.ev->worst_sse();
    if (!grad.empty()) {
      Eigen::Map<Eigen::VectorXd> g(grad.data(), grad.size());
      g.setZero();
      if (r.out.ok) {
        const Eigen::VectorXd& y0 = r.out.predicted;
        const ModelValues model = [&](const Eigen::VectorXd& at, Eigen::VectorXd& y) {
          const Evaluations::Record q = s.ev->run(at, CalibrationPhase::kSearch);
          y = q.out.predicted;
          return q.out.ok;
        };
        const ModelJacobian mj = model_jacobian(
            model, c, y0, s.lower, s.upper, s.settings->jacobian_step, DifferenceScheme::kForward);
        Eigen::VectorXd wr = y0 - s.problem->y;
        if (s.problem->weights.size()) wr = wr.cwiseProduct(s.problem->weights);
        if (mj.ok)  // dS/dv_j = 2 (J^T W r)_j width_j
          g = (2.0 / s.normalization) * s.width.cwiseProduct(mj.jacobian.transpose() * wr);
      }
    }
    return sse / s.normalization;
  } catch (const Interrupted&) {
    s.interrupted = true;
    throw nlopt::forced_stop();
  }
}

nlopt::algorithm nlopt_algorithm(CalibrationAlgorithm a) {
  return a == CalibrationAlgorithm::kGradient ? nlopt::LD_SLSQP : nlopt::LN_BOBYQA;
}

int run_search(Search& search, const Eigen::VectorXd& start, std::string& algorithm) {
  const CalibrationSettings& s = *search.settings;
  const auto n = static_cast<unsigned>(start.size());
  const bool gradient = s.algorithm == CalibrationAlgorithm::kGradient;
  const nlopt::algorithm a = nlopt_algorithm(s.algorithm);
  algorithm = nlopt_algorithm_name(a);
  nlopt::opt opt(a, n);
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_min_objective(search_objective, &search);
  opt.set_xtol_abs(s.xtol);
  opt.set_ftol_rel(s.ftol_rel);
  opt.set_maxeval(gradient ? std::max(1, s.max_evaluations / static_cast<int>(n + 1))
                           : s.max_evaluations);
  if (!gradient) opt.set_initial_step(s.initial_step);
  std::vector<double> v(n);
  for (unsigned j = 0; j < n; ++j) v[j] = (start[j] - search.lower[j]) / search.width[j];
  double f = 0;
  return optimize_returning_code(opt, v, f);
}

// Jacobian, covariance, intervals, ellipsoid, correlation and identifiability at the best point.
bool fill_inference(const CalibrationProblem& p, const CalibrationSettings& s, Evaluations& ev,
                    const Search& search, CalibrationResult& out) {
  const Evaluations::Record best = *ev.best();
  const ModelValues model = [&](const Eigen::VectorXd& at, Eigen::VectorXd& y) {
    const Evaluations::Record q = ev.run(at, CalibrationPhase::kJacobian);
    y = q.out.predicted;
    return q.out.ok;
  };
  const ModelJacobian mj = model_jacobian(model, best.c, best.out.predicted, search.lower,
                                          search.upper, s.jacobian_step);
  out.jacobian = mj.jacobian;
  out.jacobian_steps = mj.steps;
  out.predicted = best.out.predicted;
  out.residuals = best.out.predicted - p.y;
  if (!mj.ok) return false;
  const Eigen::VectorXd sqrt_w =
      p.weights.size() ? p.weights.cwiseSqrt().eval() : Eigen::VectorXd::Ones(p.y.size()).eval();
  FitResult stats;
  stats.parameters = best.c;
  stats.confidence = s.confidence;
  fill_statistics(sqrt_w.asDiagonal() * mj.jacobian, sqrt_w.cwiseProduct(out.residuals), {}, stats);
  out.num_points = stats.num_points;
  out.dof = stats.dof;
  out.rmse = stats.rmse;
  out.residual_std_dev = stats.residual_std_dev;
  out.covariance = stats.covariance;
  out.std_errors = stats.std_errors;
  out.ci_lower = stats.ci_lower;
  out.ci_upper = stats.ci_upper;
  // How far the search stopped from the optimum of the linearised problem: the Gauss-Newton step
  // from the best point, in standard errors (Bates & Watts 1988, sec. 2.2: the increment that
  // minimises |W^1/2 (r + J d)|). Small against 1: the reported point is the optimum as far as
  // the data can tell.
  const Eigen::VectorXd step = (sqrt_w.asDiagonal() * mj.jacobian)
                                   .colPivHouseholderQr()
                                   .solve(-sqrt_w.cwiseProduct(out.residuals));
  out.gauss_newton_step = step;
  out.distance_to_optimum = (step.array() / stats.std_errors.array()).abs().maxCoeff();
  out.correlation = correlation_matrix(stats.covariance);
  if (stats.covariance.allFinite() && stats.dof >= 1)
    out.ellipsoid = confidence_ellipsoid(stats.covariance, stats.dof, s.confidence);
  out.identifiability =
      assess_identifiability(sqrt_w.asDiagonal() * mj.jacobian, out.correlation, s.limits);
  return true;
}

}  // namespace

const char* to_string(CalibrationStatus status) {
  switch (status) {
    case CalibrationStatus::kConverged:
      return "converged";
    case CalibrationStatus::kBudgetExhausted:
      return "budget_exhausted";
    case CalibrationStatus::kInterrupted:
      return "interrupted";
    case CalibrationStatus::kFailed:
      return "failed";
  }
  return "?";
}

CalibrationResult calibrate(const CalibrationProblem& p, const CalibrationSettings& s) {
  check_problem(p, s);
  const auto t0 = Clock::now();
  const auto np = static_cast<Eigen::Index>(p.parameters.size());
  CalibrationResult out;
  out.confidence = s.confidence;
  Search search;
  search.lower.resize(np);
  search.upper.resize(np);
  out.start.resize(np);
  for (Eigen::Index j = 0; j < np; ++j) {
    out.names.push_back(p.parameters[j].name);
    search.lower[j] = p.parameters[j].lower;
    search.upper[j] = p.parameters[j].upper;
    out.start[j] = p.parameters[j].start;
  }
  search.width = search.upper - search.lower;
  search.problem = &p;
  search.settings = &s;
  Evaluations ev(p, s, out.evaluations);
  search.ev = &ev;
  const auto finish = [&](CalibrationStatus status, std::string reason) {
    out.status = status;
    out.reason = std::move(reason);
    if (const auto* b = ev.best()) {
      out.parameters = b->c;
      out.sse = b->sse;
    }
    out.at_bound.assign(np, false);
    for (Eigen::Index j = 0; out.parameters.size() == np && j < np; ++j)
      out.at_bound[j] = std::min(out.parameters[j] - search.lower[j],
                                 search.upper[j] - out.parameters[j]) <= 1e-6 * search.width[j];
    out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return out;
  };

  try {
    const Evaluations::Record first = ev.run(out.start, CalibrationPhase::kSearch);
    if (!first.out.ok)
      return finish(CalibrationStatus::kFailed,
                    "the model fails at the starting values: " + first.out.failure);
    out.sse_start = first.sse;
  } catch (const Interrupted&) {
    return finish(CalibrationStatus::kInterrupted, "interrupted at the first evaluation");
  }
  search.normalization = out.sse_start > 0.0 ? out.sse_start : 1.0;
  out.nlopt_code = run_search(search, out.start, out.algorithm);
  const std::string stop = "NLopt " + out.algorithm + " " + nlopt_code_name(out.nlopt_code);
  if (search.interrupted)
    return finish(CalibrationStatus::kInterrupted, "interrupted during the search (" + stop + ")");
  if (is_nlopt_failure(out.nlopt_code))
    return finish(CalibrationStatus::kFailed, stop + ": NLopt reports a failure");
  const CalibrationStatus status = out.nlopt_code == nlopt::MAXEVAL_REACHED
                                       ? CalibrationStatus::kBudgetExhausted
                                       : CalibrationStatus::kConverged;
  try {
    out.statistics_available = fill_inference(p, s, ev, search, out);
  } catch (const Interrupted&) {
    return finish(CalibrationStatus::kInterrupted,
                  stop + "; interrupted while computing the Jacobian at the optimum");
  }
  if (!out.statistics_available)
    return finish(CalibrationStatus::kFailed,
                  stop +
                      "; the model failed at every finite-difference point of a parameter: "
                      "no Jacobian at the optimum");
  return finish(status, stop);
}

std::string calibration_algorithm_name(CalibrationAlgorithm algorithm) {
  return nlopt_algorithm_name(nlopt_algorithm(algorithm));
}

}  // namespace si::fit
