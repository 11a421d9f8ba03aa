// Settings of the Newton corrector and of a continuation run. One struct each, validated by
// validate() (every entry point calls it first): errors throw std::invalid_argument naming the
// field and its value, e.g. "continuation.step_min = 2 > step_max = 1".
// Meaning of every field: docs/theory/continuation.md.
#pragma once

#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace si::cont {

// Writes `content` to the file `path`, replacing it atomically (readers see the old file or the
// new one, never a part). The caller's: the library does no file output of its own.
using FileWriter = std::function<void(const std::string& path, const std::string& content)>;

// The KINSOL Newton corrector (kinsol_corrector.hpp). Convergence: ||F||_inf <= tol with
// tol = relative_tolerance * max(||F(x_start)||_inf, residual_scale).
struct NewtonSettings {
  double relative_tolerance = 1e-10;
  // Absolute floor of the tolerance, in units of F: the magnitude of the terms of F that cancel
  // at a solution (e.g. the external load). It keeps the tolerance above roundoff when the
  // starting residual is already small (a good predictor). 0 = purely relative (solve_at only).
  double residual_scale = 1.0;
  int max_iterations = 15;
  bool line_search = true;
  // Largest Newton step (L2 norm of the update); 0 = 1000 * max(1, ||x_start||_2). KINSOL's own
  // default is 1 when x_start = 0, which truncates steps (docs/toolchain.md §3 pitfall 2).
  double max_step = 0.0;
  // Give up once ||R||_2 is above stall_ratio times its value stall_window iterations before
  // (0 = never): a corrector whose line search creeps along (each step cut to a sliver of the
  // Newton step) rarely converges, and every iteration of it costs a factorization that a
  // shorter continuation step would use better. Measured where it bites (docs/performance.md):
  // a 0.156 mm step of the 250k-unknown cap at 9.68 mm went ||R||_inf 695 -> 503 -> 495 ->
  // 493.5 -> ... and failed after 21 iterations.
  int stall_window = 0;
  double stall_ratio = 0.9;

  void validate(const std::string& prefix = "newton") const;
};

enum class Method { kNatural, kPseudoArclength };
enum class Predictor { kTangent, kSecant };

// "natural" | "pseudo_arclength"; throws std::invalid_argument for anything else.
Method parse_method(const std::string& name);
std::string method_name(Method method);
// "tangent" | "secant"; throws std::invalid_argument for anything else.
Predictor parse_predictor(const std::string& name);
std::string predictor_name(Predictor predictor);

// Inflection of monitor `monitor` plotted against monitor `against` (sign change of
// d2(monitor)/d(against)^2), e.g. the paper's critical force: T_N against k11.
struct InflectionPair {
  std::string monitor;
  std::string against;
};

// A monitor reaching a level (m = level), located as a zero crossing of m - level, e.g. a
// failure index reaching 1.
struct LevelCrossing {
  std::string monitor;
  double level = 0.0;
  // The location stops once |m - level| <= value_tolerance (monitor units; 0: by the bracket's
  // width alone, event_tolerance): event_location.hpp locate_root.
  double value_tolerance = 0.0;
};

// A step the tracer retries: the corrector did not converge, the point could not be analysed or
// the tangent turned too far (the reason says which). The step is retried at `retry` (half of
// `step`), or the run ends when `step` was already step_min (retry = 0).
struct StepFailure {
  double p = 0.0;     // of the point the step started from
  double step = 0.0;  // the failed step's size
  double retry = 0.0;
  std::string reason;
};

struct Settings {
  Method method = Method::kPseudoArclength;
  Predictor predictor = Predictor::kTangent;
  // pseudo_arclength's corrector where the branch is steep in p: a step whose unit tangent has
  // |w dp/ds| >= natural_corrector_slope is corrected at the fixed p of its predictor, the local
  // parameterisation of Rheinboldt & Burkardt (1983) with p as the local parameter. Each Newton
  // iteration then solves with J alone, where Keller's bordered system needs J^-1 dF/dp as well
  // (two solves). Near a fold (smaller slopes), or when the corrector at fixed p fails or leaves
  // the step, Keller's step. 0 = always Keller's.
  double natural_corrector_slope = 0.0;
  // Initial direction: the sign of dp along the first tangent (+1 or -1). Later steps are
  // oriented by the previous tangent, never by the previous parameter increment.
  int direction = 1;

  // Step sizes: arclength for pseudo_arclength (in the norm sqrt(<dx,dx> + w^2 dp^2)), |dp| for
  // natural.
  double step_initial = 1e-2;
  double step_min = 1e-8;
  double step_max = 1.0;
  // Step adaptation after a converged step: ds *= clamp(target / iterations, 1/2, growth_max).
  int target_iterations = 4;
  double step_growth_max = 2.0;
  // A target (bound or parameter value) no further than (1 + landing_stretch) steps ahead is
  // landed on by one step, stretched (its parameter increment w |dp| never beyond step_max),
  // instead of a step and a sliver after it (docs/theory/continuation.md §3). 0 = land only on
  // targets within a step.
  double landing_stretch = 0.3;
  // A failed step is retried with ds / 2 down to step_min; a failure at step_min ends the run.
  // A step whose tangent turned by more than this is treated as failed (guards against jumping
  // to another branch).
  double max_turn_deg = 60.0;
  // Told of each failed step as it happens (a step that keeps failing is how a stall shows;
  // each failure may cost many solves). Empty: none.
  std::function<void(const StepFailure&)> on_step_failure;

  // Parameter bounds: the run stops at the bound, landed on exactly (the last point has p = bound):
  // the step that would cross it is shortened to reach it (docs/theory/continuation.md §3).
  double p_min = -std::numeric_limits<double>::infinity();
  double p_max = std::numeric_limits<double>::infinity();
  int max_steps = 1000;
  // Weight w of the parameter in the arclength norm (its unit against x's inner product).
  double parameter_weight = 1.0;

  NewtonSettings newton;

  // Strictly increasing parameter values hit exactly: a step that would pass one is shortened to
  // land on it. natural: they must lie in the direction of travel from p0 and the run completes
  // at the last one. pseudo_arclength: each is landed on whenever the branch crosses it (away
  // from a fold of p), and the run goes on to a bound.
  std::vector<double> parameter_values;

  // Events (events.hpp), located to event_tolerance in arclength (|dp| for natural).
  bool detect_limit_points = true;
  std::vector<std::string> extremum_monitors;
  std::vector<std::string> zero_crossing_monitors;
  std::vector<LevelCrossing> level_crossings;  // reported as zero crossings of m - level
  std::vector<InflectionPair> inflections;
  bool detect_signature_changes = true;
  bool locate_signature_changes = true;
  bool detect_bifurcations = false;  // needs Problem::jacobian_sign()
  double event_tolerance = 1e-8;
  int event_max_iterations = 80;

  // Extrema of dm/dp along the branch, the inflections of m against the parameter (slope_max,
  // slope_min events): for a force monitor, slope_min is the minimum tangent stiffness.
  std::vector<std::string> slope_extremum_monitors;
  // Monitors whose slope dm/ds the caller wants at every point (Point::monitor_slopes), besides
  // those the events above need; the others' slopes are NaN, their off-branch evaluations saved.
  std::vector<std::string> slope_monitors;
  // The curve-feature detector (inflections and slope extrema; docs/theory/continuation.md,
  // "Curve features"): a point's indicator g has a sign only when |g| exceeds noise_factor times
  // its error estimate and the curvature of the curve in its own scale (each coordinate divided
  // by its range over the branch so far) exceeds curvature_tolerance; a sign change between two
  // such points is confirmed on `refinement` sub-intervals of the step, each re-solved, and
  // reported only inside a sub-interval without a signature change.
  double feature_noise_factor = 4.0;
  double feature_curvature_tolerance = 1e-3;
  int feature_refinement = 4;

  // Stability (Problem::stability) at every point: the number of lowest eigenpairs computed,
  // 0 = off (nothing computed, no cost). A change of the number of negative eigenvalues between
  // two points is a stability_change event, located on the eigenvalue that crosses zero (or by
  // bisection on the count when fewer eigenpairs are computed than the count reaches).
  int stability_modes = 0;
  bool locate_stability_changes = true;

  // Checkpoints (checkpoint.hpp): written atomically every checkpoint_interval accepted steps
  // (after the callback has seen the point) and when the run ends, except when the callback
  // stopped it: a stopped run keeps its last periodic checkpoint, from which a resume repeats
  // the points after it bit for bit (see Problem::reset_solver_caches). They are written by
  // checkpoint_writer (required with a path). Empty path = none.
  std::string checkpoint_path;
  FileWriter checkpoint_writer;
  int checkpoint_interval = 0;
  // The caller's own record of the run (e.g. the quantities it derived from each point), saved
  // in the same file by the same atomic write, so that the two can never be out of step;
  // returned as Checkpoint::attachment. Empty: none.
  std::function<nlohmann::json()> checkpoint_attachment;
  // false: the checkpoint keeps x only for the current and previous state, not for every point
  // and event (a resumed branch then has empty x before the checkpoint and in the events found
  // before it). For large problems, where every point's and event's x would make each checkpoint
  // O(steps * n): 77 MB of JSON at 1e5 unknowns with the events' x, on the cap at 10 mm.
  bool checkpoint_keeps_x = true;

  void validate() const;
};

}  // namespace si::cont
