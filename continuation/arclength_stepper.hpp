// Internal to the library: Keller's augmented system and the pseudo-arclength Stepper, shared by
// pseudo_arclength() and switch_branch(). Theory: docs/theory/continuation.md §3.
#pragma once

#include "continuation/kinsol_corrector.hpp"
#include "continuation/tracer.hpp"

namespace si::cont {

// The augmented system in u = (x, p): F(x, p) and Keller's arclength constraint
// <d_x, x - x_a> + w^2 d_p (p - p_a) = sigma, solved with the bordered linear solve.
class ArclengthSystem final : public NonlinearSystem {
 public:
  ArclengthSystem(Problem& problem, BorderedSolver& bordered, const Point& a, const Vector& d_x,
                  double d_p, double sigma)
      : problem_(problem), bordered_(bordered), a_(a), d_x_(d_x), d_p_(d_p), sigma_(sigma) {}
  bool residual(const Vector& u, Vector& r) override;
  bool setup(const Vector& u) override;
  bool solve(Vector& b) override;
  std::string failure() const override { return problem_.failure(); }
  // The last unknown is p (the arclength row).
  std::string unknown_name(int i) const override {
    return i < problem_.size() ? problem_.unknown_name(i) : "the arclength constraint";
  }

 private:
  Problem& problem_;
  BorderedSolver& bordered_;
  const Point& a_;
  const Vector& d_x_;
  double d_p_;
  double sigma_;
};

// (x; p) stacked into u.
Vector stack(const Vector& x, double p);

class ArclengthStepper final : public Stepper {
 public:
  ArclengthStepper(Problem& problem, BorderedSolver& bordered, const Settings& settings)
      : problem_(problem), bordered_(bordered), settings_(settings) {}

  Method method() const override { return Method::kPseudoArclength; }
  double distance_to_target(const State&) const override;
  bool finished(const State&) const override { return false; }
  StepResult step(const State& from, double ds) override;
  double sigma_of(const State& from, const StepResult& step, const Vector& x,
                  double p) const override;
  bool solve_on_segment(const State& from, const StepResult& step, double sigma,
                        const SegmentChord* chord, Vector& x, double& p) override;

 private:
  // The unit tangent at the current point, or the unit secant from the previous point.
  void direction(const State& from, Vector& d_x, double& d_p) const;
  // Whether the step of ds from the current point may be corrected at fixed p
  // (Settings::natural_corrector_slope): the branch is steep in p there and, by the change of
  // dp/ds since the previous point, stays so over the step (no fold of p within reach).
  bool steep_ahead(const State& from, double ds) const;
  // The bound or parameter value that the predictor u_a + ds d reaches first, if it reaches one
  // (away from a fold: w |d_p| >= kFoldSlope); the landing is the step to it.
  bool landing_target(double p_a, double ds, double d_p, double& target) const;
  // The step to p = target: predictor u_a + (target - p_a) / d_p d, corrected at the fixed
  // parameter target (natural corrector on the hyperplane p = target), from the problem's own
  // start `own` first if it has one (Problem::corrector_start). Used to land on a target and,
  // where the branch is steep in p (Settings::natural_corrector_slope) or the problem has its
  // own start, for any step.
  StepResult correct_at(const State& from, const Vector& d_x, double d_p, double target,
                        const Vector& own);
  // Keller's step of arclength ds along d.
  StepResult arclength_step(const State& from, const Vector& d_x, double d_p, double ds);

  Problem& problem_;
  BorderedSolver& bordered_;
  const Settings& settings_;
};

}  // namespace si::cont
