#include "continuation/arclength_stepper.hpp"

#include <cmath>
#include <limits>

namespace si::cont {

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
  const Point& a = from.current.point;
  StepResult out;
  direction(from, out.direction_x, out.direction_p);
  out.sigma_end = ds;
  Vector u = stack(a.x + ds * out.direction_x, a.p + ds * out.direction_p);
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
                                        Vector& x, double& p) {
  const Point& a = from.current.point;
  const double t = sigma / step.sigma_end;
  ArclengthSystem system(problem_, bordered_, a, step.direction_x, step.direction_p, sigma);
  // Chord predictor first; if the corrector fails from there (e.g. it starts exactly on a
  // singular J), the predictor along the step direction.
  Vector u = stack(a.x + t * (step.x - a.x), a.p + t * (step.p - a.p));
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
