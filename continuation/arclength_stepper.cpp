#include "continuation/arclength_stepper.hpp"

#include <cmath>
#include <limits>

namespace si::cont {
namespace {

// |w dp/ds| of the unit tangent below which the branch is near a fold of p: no landing there (the
// Jacobian at fixed p is nearly singular), Keller's step instead.
constexpr double kFoldSlope = 1e-3;
// How many steps ahead dp/ds must stay steep for a step to be corrected at fixed p
// (ArclengthStepper::steep_ahead).
constexpr double kFoldMargin = 4.0;

}  // namespace

bool ArclengthSystem::residual(const Vector& u, Vector& r) {
  const Eigen::Index n = a_.x.size();
  Vector f;
  if (!problem_.residual(u.head(n), u(n), f) || f.size() != n) return false;
  r.resize(n + 1);
  r.head(n) = f;
  r(n) = bordered_.inner(d_x_, d_p_, u.head(n) - a_.x, u(n) - a_.p) - sigma_;
  return true;
}

bool ArclengthSystem::setup(const Vector& u) {
  const Eigen::Index n = a_.x.size();
  return bordered_.setup(u.head(n), u(n));
}

bool ArclengthSystem::solve(Vector& b) {
  const Eigen::Index n = a_.x.size();
  Vector y = b.head(n);
  double q = 0.0;
  if (!bordered_.solve(d_x_, d_p_, y, b(n), q)) return false;
  b.head(n) = y;
  b(n) = q;
  return true;
}

Vector stack(const Vector& x, double p) {
  Vector u(x.size() + 1);
  u << x, p;
  return u;
}

double ArclengthStepper::distance_to_target(const State&) const {
  return std::numeric_limits<double>::infinity();
}

StepResult ArclengthStepper::step(const State& from, double ds) {
  Vector d_x;
  double d_p = 0.0;
  direction(from, d_x, d_p);
  const Point& a = from.current.point;
  const double p_a = a.p;
  double target = 0.0;
  if (landing_target(p_a, ds, d_p, target)) {
    StepResult landed =
        correct_at(from, d_x, d_p, target, problem_.corrector_start(a.x, p_a, target));
    landed.landed = landed.converged;
    if (landed.converged) return landed;
  } else {
    // At the predictor's p: where the branch is steep in p over the step, or where the problem
    // has its own start there (the steep test, which reads the previous tangent, cannot judge a
    // branch's first step), away from a fold of p.
    const double p = p_a + ds * d_p;
    const Vector own = bordered_.weight() * std::abs(d_p) >= kFoldSlope
                           ? problem_.corrector_start(a.x, p_a, p)
                           : Vector();
    if (own.size() == a.x.size() || steep_ahead(from, ds)) {
      StepResult steep = correct_at(from, d_x, d_p, p, own);
      if (steep.converged) return steep;
    }
  }
  // No target within reach, or no solution at it near the predictor (e.g. a fold just before
  // it): Keller's step; the tracer cuts it at a bound it crosses (Tracer::clip_to_target).
  return arclength_step(from, d_x, d_p, ds);
}

bool ArclengthStepper::steep_ahead(const State& from, double ds) const {
  const double slope = settings_.natural_corrector_slope;
  const Point& a = from.current.point;
  const double w = bordered_.weight();
  if (!(slope > 0.0) || !(w * std::abs(a.tangent_p) >= slope) ||
      !std::isfinite(from.previous_tangent_p) || !(a.step > 0.0))
    return false;
  // dp/ds, extrapolated linearly from the last step's change over kFoldMargin steps ahead, must
  // stay above the slope: near a fold it falls faster than linearly (the roof's switched
  // branch: 0.90, 0.75, then its fold 0.45 of arclength on, measured), and past a fold of p
  // this branch has no solution at the predictor's p while another branch crossing the fold
  // point may: the fixed-p corrector would jump to it.
  const double rate = (a.tangent_p - from.previous_tangent_p) / a.step;
  const double ahead = a.tangent_p + rate * kFoldMargin * ds;
  return ahead * a.tangent_p > 0.0 && w * std::abs(ahead) >= slope;
}

bool ArclengthStepper::landing_target(double p_a, double ds, double d_p, double& target) const {
  if (!(bordered_.weight() * std::abs(d_p) >= kFoldSlope)) return false;
  // The stretch keeps the step's p-part w |dp| within step_max; its arclength may exceed it by
  // the x-part alone (a path whose step_max is its depth_max lands on it in one step).
  const double ahead = d_p > 0.0 ? 1.0 : -1.0;
  const double reach = p_a + ahead * stretched(ds * std::abs(d_p),
                                               settings_.step_max / bordered_.weight(), settings_);
  target = d_p > 0.0 ? settings_.p_max : settings_.p_min;
  for (double v : settings_.parameter_values)
    if (ahead * (v - p_a) > 0.0 && ahead * (v - target) < 0.0) target = v;
  return std::isfinite(target) && ahead * (reach - target) >= 0.0;
}

StepResult ArclengthStepper::correct_at(const State& from, const Vector& d_x, double d_p,
                                        double target, const Vector& own) {
  const Point& a = from.current.point;
  const double ds = (target - a.p) / d_p;  // the predictor's arclength to p = target
  StepResult out;
  out.direction_x = d_x;
  out.direction_p = d_p;
  out.p = target;
  // The corrector at fixed p may leave the hyperplane's neighbourhood: accept only a point ahead
  // along d and not beyond twice the predictor's arclength (else a jump along the branch).
  const auto on_step = [&](const Vector& x) {
    const double sigma = sigma_of(from, out, x, target);
    return sigma > 0.0 && sigma <= 2.0 * ds;
  };
  const NewtonResult r = correct_at_parameter(problem_, target, own, a.x + ds * d_x,
                                              settings_.newton, on_step, out.x, out.own_start);
  out.iterations = r.iterations;
  out.reason = r.reason;
  out.sigma_end = sigma_of(from, out, out.x, out.p);
  out.converged = r.converged;
  return out;
}

StepResult ArclengthStepper::arclength_step(const State& from, const Vector& d_x, double d_p,
                                            double ds) {
  const Point& a = from.current.point;
  StepResult out;
  out.direction_x = d_x;
  out.direction_p = d_p;
  out.sigma_end = ds;
  Vector u = stack(a.x + ds * d_x, a.p + ds * d_p);
  ArclengthSystem system(problem_, bordered_, a, out.direction_x, out.direction_p, ds);
  const NewtonResult r = newton_solve(system, u, settings_.newton);
  out.x = u.head(a.x.size());
  out.p = u(a.x.size());
  out.converged = r.converged;
  out.iterations = r.iterations;
  out.reason = r.reason;
  return out;
}

double ArclengthStepper::sigma_of(const State& from, const StepResult& step, const Vector& x,
                                  double p) const {
  const Point& a = from.current.point;
  return bordered_.inner(step.direction_x, step.direction_p, x - a.x, p - a.p);
}

bool ArclengthStepper::solve_on_segment(const State& from, const StepResult& step, double sigma,
                                        const SegmentChord* chord, Vector& x, double& p) {
  const Point& a = from.current.point;
  ArclengthSystem system(problem_, bordered_, a, step.direction_x, step.direction_p, sigma);
  // Chord predictor first; if the corrector fails from there (e.g. it starts exactly on a
  // singular J), the predictor along the step direction.
  Vector u;
  if (chord) {
    const double t = (sigma - chord->sigma_lo) / (chord->sigma_hi - chord->sigma_lo);
    u = stack(chord->lo.x + t * (chord->hi.x - chord->lo.x),
              chord->lo.p + t * (chord->hi.p - chord->lo.p));
  } else {
    const double t = sigma / step.sigma_end;
    u = stack(a.x + t * (step.x - a.x), a.p + t * (step.p - a.p));
  }
  if (!newton_solve(system, u, settings_.newton).converged) {
    u = stack(a.x + sigma * step.direction_x, a.p + sigma * step.direction_p);
    if (!newton_solve(system, u, settings_.newton).converged) return false;
  }
  x = u.head(a.x.size());
  p = u(a.x.size());
  return true;
}

void ArclengthStepper::direction(const State& from, Vector& d_x, double& d_p) const {
  const Point& a = from.current.point;
  if (settings_.predictor == Predictor::kSecant && from.has_previous &&
      from.previous_x.size() == a.x.size()) {
    d_x = a.x - from.previous_x;
    d_p = a.p - from.previous_p;
    const double norm = std::sqrt(bordered_.inner(d_x, d_p, d_x, d_p));
    if (norm > 0.0) {
      d_x /= norm;
      d_p /= norm;
      return;
    }
  }
  d_x = from.current.tangent_x;
  d_p = a.tangent_p;
}

}  // namespace si::cont
