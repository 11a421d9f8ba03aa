#include "continuation/natural.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "continuation/kinsol_corrector.hpp"
#include "continuation/tracer.hpp"

namespace si::cont {
namespace {

class NaturalStepper final : public Stepper {
 public:
  NaturalStepper(Problem& problem, const Settings& settings, double p0)
      : problem_(problem), settings_(settings), dir_(settings.direction) {
    for (std::size_t i = 0; i < settings.parameter_values.size(); ++i) {
      const double v = settings.parameter_values[i];
      if (dir_ * (v - p0) < 0.0)
        throw std::invalid_argument(
            "continuation.parameter_values[" + std::to_string(i) + "] = " + std::to_string(v) +
            " lies behind p0 = " + std::to_string(p0) + " in direction " + std::to_string(dir_));
    }
  }

  Method method() const override { return Method::kNatural; }

  double distance_to_target(const State& from) const override {
    const double target = next_target(from.current.point.p);
    return std::isfinite(target) ? dir_ * (target - from.current.point.p)
                                 : std::numeric_limits<double>::infinity();
  }

  bool finished(const State& state) const override {
    const auto& values = settings_.parameter_values;
    if (values.empty()) return false;
    return state.current.point.p == (dir_ > 0 ? values.back() : values.front());
  }

  StepResult step(const State& from, double ds) override {
    const Point& a = from.current.point;
    const double target = next_target(a.p);
    // Hit targets exactly: p_a + (target - p_a) need not round to target.
    const double p =
        std::isfinite(target) && ds >= dir_ * (target - a.p) ? target : a.p + dir_ * ds;
    StepResult out;
    out.p = p;
    out.direction_p = dir_;
    out.sigma_end = dir_ * (p - a.p);
    const NewtonResult r = correct_at_parameter(
        problem_, p, problem_.corrector_start(a.x, a.p, p), predict(from, p), settings_.newton,
        [](const Vector&) { return true; }, out.x, out.own_start);
    out.converged = r.converged;
    out.iterations = r.iterations;
    out.reason = r.reason;
    return out;
  }

  double sigma_of(const State& from, const StepResult&, const Vector&, double p) const override {
    return dir_ * (p - from.current.point.p);
  }

  bool solve_on_segment(const State& from, const StepResult& step, double sigma,
                        const SegmentChord* chord, Vector& x, double& p) override {
    const Point& a = from.current.point;
    p = a.p + dir_ * sigma;
    // Chord predictor first; if the corrector fails from there, the step's own predictor.
    x = chord ? Vector(chord->lo.x +
                       ((sigma - chord->sigma_lo) / (chord->sigma_hi - chord->sigma_lo)) *
                           (chord->hi.x - chord->lo.x))
              : Vector(a.x + (sigma / step.sigma_end) * (step.x - a.x));
    if (solve_at(problem_, x, p, settings_.newton).converged) return true;
    x = predict(from, p);
    return solve_at(problem_, x, p, settings_.newton).converged;
  }

 private:
  // The nearest parameter value or bound strictly ahead of p; +-infinity if none.
  double next_target(double p) const {
    double best = dir_ > 0 ? settings_.p_max : settings_.p_min;
    for (double v : settings_.parameter_values)
      if (dir_ * (v - p) > 0.0 && dir_ * (v - best) < 0.0) best = v;
    return best;
  }

  Vector predict(const State& from, double p) const {
    const Point& a = from.current.point;
    const double dp = p - a.p;
    if (settings_.predictor == Predictor::kSecant && from.has_previous &&
        from.previous_x.size() == a.x.size() && from.previous_p != a.p)
      return a.x + (dp / (a.p - from.previous_p)) * (a.x - from.previous_x);
    if (a.tangent_p == 0.0) return a.x;
    return a.x + (dp / a.tangent_p) * from.current.tangent_x;  // dx/dp = t_x / t_p
  }

  Problem& problem_;
  const Settings& settings_;
  int dir_;
};

}  // namespace

Branch natural(Problem& problem, Vector x0, double p0, const Settings& settings,
               const Callback& callback) {
  settings.validate();
  NaturalStepper stepper(problem, settings, p0);
  BorderedSolver bordered(problem, settings.parameter_weight);
  return trace(problem, stepper, bordered,
               {x0, p0, Vector(), static_cast<double>(settings.direction), 0}, settings, callback,
               std::nullopt);
}

Branch natural(Problem& problem, const Checkpoint& resume, const Settings& settings,
               const Callback& callback) {
  settings.validate();
  const double p0 =
      resume.branch.points.empty() ? resume.state.current.point.p : resume.branch.points.front().p;
  NaturalStepper stepper(problem, settings, p0);
  BorderedSolver bordered(problem, settings.parameter_weight);
  return trace(problem, stepper, bordered, Start{}, settings, callback, resume);
}

}  // namespace si::cont
