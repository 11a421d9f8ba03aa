// The loop shared by natural and pseudo-arclength continuation: start, step control (growth by
// Newton iteration count, halving on failure), parameter bounds, events, adaptation,
// checkpoints, callback. What differs between the two methods (predictor, corrector, what a
// step measures) is a Stepper. Internal to the library: users call natural.hpp and
// pseudo_arclength.hpp.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "continuation/checkpoint.hpp"
#include "continuation/event_location.hpp"
#include "continuation/kinsol_corrector.hpp"

namespace si::cont {

struct StepResult {
  bool converged = false;
  Vector x;
  double p = 0.0;
  int iterations = 0;
  std::string reason;
  // The segment from the start of the step to (x, p), for events: its local coordinate sigma
  // runs from 0 to sigma_end along `direction` (pseudo-arclength) or along p (natural).
  Vector direction_x;
  double direction_p = 0.0;
  double sigma_end = 0.0;
  // The step was shortened to land on a bound or a Settings::parameter_values entry (its p is
  // that value exactly): the next step grows from the nominal size, not from this one.
  bool landed = false;
  // Corrected from the problem's own start (Problem::corrector_start), not from the predictor:
  // its iterations say nothing of the predictor's error, which the step control reads.
  bool own_start = false;
};

class Stepper {
 public:
  virtual ~Stepper() = default;
  virtual Method method() const = 0;
  // The largest step from `from` before a parameter value that must be hit exactly (natural:
  // the next Settings::parameter_values entry or bound ahead); +infinity if none.
  virtual double distance_to_target(const State& from) const = 0;
  // True when `state` sits on the last target (natural with parameter_values: completed).
  virtual bool finished(const State& state) const = 0;
  // One predictor-corrector step of size ds from `from`.
  virtual StepResult step(const State& from, double ds) = 0;
  // The local coordinate of (x, p) on the segment of `step`.
  virtual double sigma_of(const State& from, const StepResult& step, const Vector& x,
                          double p) const = 0;
  // (x, p) on the segment of `step` at local coordinate sigma, from the predictor on `chord`
  // (nullptr: the chord of the step's ends).
  virtual bool solve_on_segment(const State& from, const StepResult& step, double sigma,
                                const SegmentChord* chord, Vector& x, double& p) = 0;
};

// How far in p a step whose nominal increment of p is dp may go to land on a target instead of
// leaving a sliver to it: min((1 + landing_stretch) dp, max(dp, limit)), limit the largest
// increment of p that step_max allows (Settings::landing_stretch).
double stretched(double dp, double limit, const Settings& settings);

// The corrector at the fixed parameter p of a step out of `from`: from the problem's own start
// `own` (Problem::corrector_start; empty: none) if the corrector ends there on a point `on_step`
// accepts, else from `predicted`. x gets the last corrector's end; converged = it converged to a
// point on_step accepts; the iterations of both correctors count; from_own = x is the end of the
// corrector from `own`.
NewtonResult correct_at_parameter(Problem& problem, double p, const Vector& own,
                                  const Vector& predicted, const NewtonSettings& settings,
                                  const std::function<bool(const Vector&)>& on_step, Vector& x,
                                  bool& from_own);

// Where a fresh run starts: the point (solved at p first), the reference that orients its first
// tangent (ref_x empty: by the sign of ref_p, i.e. Settings::direction) and the branch id its
// points carry.
struct Start {
  Vector x;
  double p = 0.0;
  Vector ref_x;
  double ref_p = 1.0;
  int branch_id = 0;
};

// Runs from a fresh start (resume empty) or from a checkpoint.
Branch trace(Problem& problem, Stepper& stepper, BorderedSolver& bordered, const Start& start,
             const Settings& settings, const Callback& callback,
             const std::optional<Checkpoint>& resume);

}  // namespace si::cont
