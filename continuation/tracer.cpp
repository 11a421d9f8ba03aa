#include "continuation/tracer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "continuation/events.hpp"
#include "continuation/kinsol_corrector.hpp"

namespace si::cont {
namespace {

constexpr double kDegree = 0.017453292519943295;  // pi / 180
// Problem::adapt rounds at one point (each one a re-solve) before the growth is taken as done.
constexpr int kMaxAdaptRounds = 10;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

class Tracer {
 public:
  Tracer(Problem& problem, Stepper& stepper, BorderedSolver& bordered, const Settings& settings,
         const Callback& callback)
      : problem_(problem),
        stepper_(stepper),
        bordered_(bordered),
        settings_(settings),
        callback_(callback) {
    branch_.monitor_names = problem.monitor_names();
    indicators_ = make_indicators(settings, branch_.monitor_names);
    needs_ = analysis_needs(indicators_, settings, branch_.monitor_names);
    if (settings.stability_modes > 0 && !problem.provides_stability())
      throw std::invalid_argument(
          "continuation.stability_modes = " + std::to_string(settings.stability_modes) +
          " but the problem does not provide stability()");
  }

  Branch run(const Start& from) {
    const Vector& x0 = from.x;
    const double p0 = from.p;
    if (x0.size() != problem_.size())
      throw std::invalid_argument("continuation: x0 has size " + std::to_string(x0.size()) +
                                  " but the problem has size " + std::to_string(problem_.size()));
    if (!(p0 >= settings_.p_min && p0 <= settings_.p_max))
      throw std::invalid_argument("continuation: p0 = " + fmt(p0) + " is outside [p_min, p_max]");
    branch_id_ = from.branch_id;
    if (start(from) && after_accept()) loop();
    return branch_;
  }

  Branch resume(const Checkpoint& checkpoint) {
    if (checkpoint.method != stepper_.method())
      throw std::invalid_argument("continuation: the checkpoint was written by " +
                                  method_name(checkpoint.method) + ", not " +
                                  method_name(stepper_.method()));
    if (checkpoint.state.current.point.x.size() != problem_.size())
      throw std::invalid_argument("continuation: the checkpoint's x has size " +
                                  std::to_string(checkpoint.state.current.point.x.size()) +
                                  " but the problem has size " + std::to_string(problem_.size()));
    if (checkpoint.branch.monitor_names != branch_.monitor_names)
      throw std::invalid_argument(
          "continuation: the checkpoint's monitors differ from the problem's");
    branch_ = checkpoint.branch;
    branch_.checkpointed = branch_.points.size();
    state_ = checkpoint.state;
    branch_id_ = state_.current.point.branch_id;
    for (const auto& point : branch_.points) scales_.include(point);
    problem_.reset_solver_caches();  // as the run that wrote the checkpoint did after it
    const Status s = branch_.status;
    if (s == Status::kCompleted || s == Status::kReachedBound || s == Status::kStartFailed)
      return branch_;
    branch_.status = Status::kRunning;
    branch_.reason.clear();
    loop();
    return branch_;
  }

 private:
  int steps() const { return static_cast<int>(branch_.points.size()) - 1; }

  double chord(const Point& a, const Point& b) const {
    const Vector dx = b.x - a.x;
    const double dp = b.p - a.p;
    return std::sqrt(bordered_.inner(dx, dp, dx, dp));
  }

  bool analyse(const Vector& x, double p, const Vector& ref_x, double ref_p, TangentPoint& out) {
    return analyse(x, p, ref_x, ref_p, needs_, out);
  }

  bool analyse(const Vector& x, double p, const Vector& ref_x, double ref_p,
               const AnalysisNeeds& needs, TangentPoint& out) {
    if (!analyse_point(problem_, bordered_, x, p, ref_x, ref_p, needs, out)) return false;
    out.point.branch_id = branch_id_;
    return true;
  }

  bool start(const Start& from) {
    Vector x = from.x;
    const NewtonResult r = solve_at(problem_, x, from.p, settings_.newton);
    if (!r.converged) return finish(Status::kStartFailed, "the start point: " + r.reason);
    if (!analyse(x, from.p, from.ref_x, from.ref_p, state_.current))
      return finish(Status::kStartFailed,
                    settings_.stability_modes > 0
                        ? "the Jacobian or the stability analysis fails at the start point"
                        : "the Jacobian cannot be factored at the start point");
    state_.current.point.newton_iterations = r.iterations;
    state_.step = settings_.step_initial;
    branch_.points.push_back(state_.current.point);
    scales_.include(state_.current.point);
    return true;
  }

  void loop() {
    while (true) {
      if (steps() >= settings_.max_steps) {
        finish(Status::kMaxSteps, "max_steps = " + std::to_string(settings_.max_steps));
        return;
      }
      const double nominal = state_.step;
      const double to_target = stepper_.distance_to_target(state_);  // natural's; else infinity
      const double ds =
          to_target <= stretched(nominal, settings_.step_max, settings_) ? to_target : nominal;
      if (!(ds > 0.0)) {  // natural, started on the bound ahead
        finish(Status::kReachedBound, "p is on the bound " + fmt(state_.current.point.p));
        return;
      }
      StepResult step;
      TangentPoint b;
      std::string why;
      if (!try_step(ds, step, b, why)) {
        ++branch_.failed_steps;
        const bool last = ds <= settings_.step_min * (1.0 + 1e-12);
        const double retry = last ? 0.0 : std::max(0.5 * ds, settings_.step_min);
        if (settings_.on_step_failure)
          settings_.on_step_failure({state_.current.point.p, ds, retry, why});
        if (last) {
          finish(Status::kStepTooSmall, "a step of " + fmt(ds) + " from p = " +
                                            fmt(state_.current.point.p) + " failed: " + why);
          return;
        }
        state_.step = retry;
        continue;
      }
      const bool at_bound = clip_to_target(step, b);
      accept(step, b, nominal, ds != nominal || step.landed);
      if (!after_accept()) return;
      if (at_bound) {
        finish(Status::kReachedBound, "p reached the bound " + fmt(b.point.p));
        return;
      }
      if (stepper_.finished(state_)) {
        finish(Status::kCompleted, "the last parameter value was reached");
        return;
      }
    }
  }

  bool try_step(double ds, StepResult& step, TangentPoint& b, std::string& why) {
    step = stepper_.step(state_, ds);
    if (!step.converged) {
      why = step.reason;
      return false;
    }
    const TangentPoint& a = state_.current;
    if (!analyse(step.x, step.p, a.tangent_x, a.point.tangent_p, b)) {
      why = "the Jacobian or dF/dp cannot be evaluated at the new point";
      return false;
    }
    const double cos_turn =
        bordered_.inner(a.tangent_x, a.point.tangent_p, b.tangent_x, b.point.tangent_p);
    if (!(cos_turn >= std::cos(settings_.max_turn_deg * kDegree))) {
      why = "the tangent turned by " + fmt(std::acos(std::clamp(cos_turn, -1.0, 1.0)) / kDegree) +
            " deg > max_turn_deg";
      return false;
    }
    return true;
  }

  // Points inside the step, analysed as `needs` says (all of needs_ by default).
  SegmentSolver segment(const StepResult& step) { return segment(step, needs_); }
  SegmentSolver segment(const StepResult& step, const AnalysisNeeds& needs) {
    return [this, &step, needs](double sigma, const SegmentChord* chord, TangentPoint& out) {
      const TangentPoint& a = state_.current;
      Vector x;
      double p = 0.0;
      return stepper_.solve_on_segment(state_, step, sigma, chord, x, p) &&
             analyse(x, p, a.tangent_x, a.point.tangent_p, needs, out);
    };
  }

  // The bound or Settings::parameter_values entry that the step from p_a to p_b went past (the
  // first one from p_a), if any. A step that lands on one (StepResult::landed) has p_b on it.
  bool crossed_target(double p_a, double p_b, double& target) const {
    target = p_b > settings_.p_max   ? settings_.p_max
             : p_b < settings_.p_min ? settings_.p_min
                                     : std::nan("");
    for (double v : settings_.parameter_values)
      if ((v - p_a) * (v - p_b) < 0.0 &&
          (std::isnan(target) || std::abs(v - p_a) < std::abs(target - p_a)))
        target = v;
    return !std::isnan(target);
  }

  // If the step went past a target (a bound, or a parameter value the landing missed because the
  // corrector carried p beyond the predictor's), replace b by the point on it: located on the
  // segment by regula falsi on p - target, then solved at p = target exactly. This costs several
  // solves; the steppers land on their targets instead (Stepper::step), so it is the exception.
  // True if b is on a bound.
  bool clip_to_target(StepResult& step, TangentPoint& b) {
    const double p = b.point.p;
    if (p == settings_.p_min || p == settings_.p_max) return true;
    double target = 0.0;
    if (!crossed_target(state_.current.point.p, p, target)) return false;
    const TangentPoint& a = state_.current;
    TangentPoint at;
    bool located = false;
    locate_root([target](const TangentPoint& tp) { return tp.point.p - target; }, {0.0, a},
                {step.sigma_end, b}, segment(step), settings_, at, located);
    Vector x = at.point.x;
    if (solve_at(problem_, x, target, settings_.newton).converged &&
        analyse(x, target, a.tangent_x, a.point.tangent_p, b)) {
      step.sigma_end = stepper_.sigma_of(state_, step, b.point.x, b.point.p);
    } else {
      b = at;  // p within event_tolerance of the target: the best available
      step.sigma_end = stepper_.sigma_of(state_, step, b.point.x, b.point.p);
    }
    step.landed = true;
    return target == settings_.p_min || target == settings_.p_max;
  }

  void accept(const StepResult& step, TangentPoint& b, double nominal, bool clipped) {
    const TangentPoint& a = state_.current;
    b.point.newton_iterations = step.iterations;
    b.point.step = step.sigma_end;
    b.point.arclength = a.point.arclength + chord(a.point, b.point);
    const int index = steps() + 1;
    scales_.include(b.point);
    // Only a stability change is located on the points' stability: the other events' points
    // skip that analysis (half the cost of path.stability on a path with a contact event per
    // step).
    AnalysisNeeds without_stability = needs_;
    without_stability.stability_modes = 0;
    AnalysisNeeds monitors_only;
    monitors_only.tangent = false;
    const auto events =
        find_events(indicators_, branch_.monitor_names, a, b, step.sigma_end,
                    {segment(step, without_stability), segment(step), segment(step, monitors_only)},
                    settings_, index, bordered_, scales_);
    branch_.points.push_back(b.point);
    branch_.events.insert(branch_.events.end(), events.begin(), events.end());
    state_.has_previous = true;
    state_.previous_x = a.point.x;
    state_.previous_p = a.point.p;
    state_.previous_tangent_p = a.point.tangent_p;
    state_.current = b;
    // Step adaptation by the Newton iteration count (Allgower & Georg 2003, §6.1, in spirit): a
    // measure of the predictor's error. A step corrected from the problem's own start measured
    // that start instead: the next step may shrink, not grow on no evidence (the 1e5-unknown
    // cap's first step, 2 iterations from the linear twin's state, doubled the second, which
    // then took 5: docs/performance.md).
    const double growth = step.own_start ? 1.0 : settings_.step_growth_max;
    const double factor =
        std::clamp(static_cast<double>(settings_.target_iterations) / std::max(step.iterations, 1),
                   0.5, growth);
    const double base = clipped ? nominal : step.sigma_end;
    state_.step = std::clamp(base * factor, settings_.step_min, settings_.step_max);
  }

  // Adaptation, callback and checkpoint after an accepted point. false = the run ends. The
  // callback comes first so that the caller's record (Settings::checkpoint_attachment) holds
  // the point; the solver caches are dropped after each checkpoint so that the run goes on as
  // one resumed from it would (Problem::reset_solver_caches).
  bool after_accept() {
    if (!adapt()) return false;
    if (callback_ && !callback_(branch_.points.back(), branch_))
      return finish(Status::kStoppedByCallback, "stopped by the callback");
    const int n = steps();
    if (settings_.checkpoint_interval > 0 && n % settings_.checkpoint_interval == 0) {
      save_state();
      problem_.reset_solver_caches();
    }
    return true;
  }

  // The old point's stability on `to`, the same point grown (its modes, of the old size, are
  // dropped: they serve only the location of a change from this point on, which analyses its
  // points afresh).
  static void keep_stability(const Point& from, TangentPoint& to) {
    Point& p = to.point;
    p.negative_eigenvalues = from.negative_eigenvalues;
    p.zero_eigenvalues = from.zero_eigenvalues;
    p.stable = from.stable;
    p.eigenvalues = from.eigenvalues;
    p.lowest_eigenvalue = from.lowest_eigenvalue;
    to.modes.clear();
  }

  // The problem may grow (Problem::adapt); the point is then re-solved at the same p, and that
  // re-solved point replaces the accepted one in the branch (the one before the growth need not
  // solve the grown problem: e.g. a node outside a contact candidate set may penetrate). Repeated
  // while the problem keeps growing at this p.
  bool adapt() {
    Vector x = state_.current.point.x;
    const double p = state_.current.point.p;
    bool adapted = false;
    // Whether every re-solve left x as the growth laid it out: the old point with its new
    // unknowns zero (e.g. contact candidates added clear of the shell, no force). Then the
    // point is the old one and so is its stability, which is copied rather than computed again.
    bool moved = false;
    for (int round = 0; round < kMaxAdaptRounds && problem_.adapt(x, p); ++round) {
      adapted = true;
      const Vector grown = x;
      const NewtonResult r = solve_at(problem_, x, p, settings_.newton);
      if (!r.converged)
        return finish(Status::kStepTooSmall, "no solution after Problem::adapt: " + r.reason);
      moved = moved || x != grown;
    }
    if (!adapted) return true;
    const Point old = state_.current.point;
    const double sign_p = old.tangent_p != 0.0 ? old.tangent_p : settings_.direction;
    AnalysisNeeds needs = needs_;
    if (!moved) needs.stability_modes = 0;
    if (!analyse(x, p, Vector(), sign_p, needs, state_.current))
      return finish(Status::kStepTooSmall, "the Jacobian cannot be factored after Problem::adapt");
    if (!moved && needs_.stability_modes > 0) keep_stability(old, state_.current);
    state_.current.point.newton_iterations = old.newton_iterations;
    state_.current.point.step = old.step;
    state_.current.point.arclength = old.arclength;
    state_.has_previous = false;
    if (!branch_.points.empty()) branch_.points.back() = state_.current.point;
    scales_.include(state_.current.point);
    return true;
  }

  // A run stopped by its callback keeps its last periodic checkpoint (see Settings): one
  // written here would resume with cold solver caches where this run had warm ones.
  bool finish(Status status, const std::string& reason) {
    branch_.status = status;
    branch_.reason = reason;
    const bool keep_last = status == Status::kStartFailed || status == Status::kStoppedByCallback;
    if (!settings_.checkpoint_path.empty() && !keep_last) save_state();
    return false;
  }

  void save_state() {
    branch_.checkpointed = branch_.points.size();
    const nlohmann::json attachment =
        settings_.checkpoint_attachment ? settings_.checkpoint_attachment() : nlohmann::json();
    save_checkpoint(settings_.checkpoint_path, {stepper_.method(), branch_, state_, attachment},
                    settings_.checkpoint_keeps_x, settings_.checkpoint_writer);
  }

  Problem& problem_;
  Stepper& stepper_;
  BorderedSolver& bordered_;
  const Settings& settings_;
  const Callback& callback_;
  std::vector<Indicator> indicators_;
  AnalysisNeeds needs_;
  int branch_id_ = 0;
  CurveScales scales_;  // the monitors' and p's extent over the accepted points
  Branch branch_;
  State state_;
};

}  // namespace

double stretched(double dp, double limit, const Settings& settings) {
  return std::min((1.0 + settings.landing_stretch) * dp, std::max(dp, limit));
}

NewtonResult correct_at_parameter(Problem& problem, double p, const Vector& own,
                                  const Vector& predicted, const NewtonSettings& settings,
                                  const std::function<bool(const Vector&)>& on_step, Vector& x,
                                  bool& from_own) {
  int iterations = 0;
  NewtonResult r;
  for (const Vector* start : {&own, &predicted}) {
    if (start->size() != predicted.size()) continue;
    x = *start;
    from_own = start == &own;
    r = solve_at(problem, x, p, settings);
    iterations += r.iterations;
    r.converged = r.converged && on_step(x);
    if (r.converged) break;
  }
  r.iterations = iterations;
  return r;
}

Branch trace(Problem& problem, Stepper& stepper, BorderedSolver& bordered, const Start& start,
             const Settings& settings, const Callback& callback,
             const std::optional<Checkpoint>& resume) {
  settings.validate();
  Tracer tracer(problem, stepper, bordered, settings, callback);
  return resume ? tracer.resume(*resume) : tracer.run(start);
}

}  // namespace si::cont
