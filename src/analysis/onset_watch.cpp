#include "analysis/onset_watch.hpp"

#include <cmath>

#include "continuation/kinsol_corrector.hpp"

namespace si {
namespace {

// The same case with linear kinematics; no damage probe (no criteria): only its force is read.
IndentationCase linear_case(const IndentationCase& spec) {
  IndentationCase c = spec;
  c.kinematics = Kinematics::kLinear;
  if (c.damage) c.damage->criteria.clear();
  return c;
}

}  // namespace

OnsetWatch::OnsetWatch(const IndentationSetup& setup)
    : twin_(linear_case(setup.spec), 1),
      fast_(*twin_.problem),
      fraction_(setup.spec.path.nonlinearity_fraction) {}

double OnsetWatch::linear_force(double h) {
  ++linear_solves_;
  return twin_.problem->indenter_force_of(fast_.multipliers(h));
}

cont::Vector OnsetWatch::linear_state(double h, const IndentationProblem& p) {
  const IndentationProblem& twin = *twin_.problem;
  if (crossed_ || !passing_ || p.size() != twin.size() ||
      p.num_shell_unknowns() != twin.num_shell_unknowns() || p.candidates() != twin.candidates())
    return {};
  // The twin's shell unknowns are the run's chart coordinates at the reference base
  // (shell_chart.hpp); its multipliers are the same candidates' in the same order.
  return fast_.solve(h);
}

void OnsetWatch::add(const PathPoint& p, const cont::Vector& z) {
  if (crossed_ || !passing_) return;
  const double h = p.state.depth;
  // A resumed run starts after its checkpoint: its first passage began before it, and the
  // bracket, if any, is behind it. Solving the twin at the resumed depth would cost a linear
  // solve per contact node (about 11,000 on the 1e6-unknown cap at 8.2 mm), for nothing: the
  // onset is then found from the points after the run (find_nonlinearity_onset).
  if (p.index > 0 && last_z_.size() == 0) {
    stop_watching();
    return;
  }
  if (p.index > 0 && !(h > last_depth_)) {  // the depth turns: the first passage ends
    stop_watching();
    return;
  }
  if (h > 0) {
    const double t_lin = linear_force(h);
    if (std::abs(p.state.force - t_lin) / std::abs(t_lin) - fraction_ >= 0) {
      crossed_ = true;
      if (last_z_.size() > 0)
        solved_ = {{last_depth_, last_z_, std::nan(""), false}, {h, z, p.state.force, false}};
      fast_.release_factor();
      return;
    }
  }
  last_depth_ = h;
  last_z_ = z;
}

void OnsetWatch::stop_watching() {
  passing_ = false;
  fast_.release_factor();
}

std::optional<std::pair<double, double>> OnsetWatch::bracket() const {
  if (solved_.size() < 2) return std::nullopt;
  return std::make_pair(solved_[0].depth, solved_[1].depth);
}

cont::Vector OnsetWatch::start_for(const IndentationProblem& p, double h) const {
  const Solved* below = nullptr;
  const Solved* above = nullptr;
  for (const Solved& s : solved_) {
    if (s.depth <= h && (!below || s.depth > below->depth)) below = &s;
    if (s.depth >= h && (!above || s.depth < above->depth)) above = &s;
  }
  if (!below) return {};
  const cont::Vector a = in_present_layout(below->z, p);
  if (!above || above->depth == below->depth || a.size() == 0) return a;
  const cont::Vector b = in_present_layout(above->z, p);
  if (b.size() != a.size()) return a;
  const double t = (h - below->depth) / (above->depth - below->depth);
  return (1 - t) * a + t * b;
}

bool OnsetWatch::solve_force(IndentationSetup& setup, double from, double h, double& force) {
  if (solved_.empty() || from != solved_.front().depth) return false;  // never crossed
  for (const Solved& s : solved_)
    if (s.trial && s.depth == h) {
      force = s.force;
      return true;
    }
  IndentationProblem& p = *setup.problem;
  // The run's last preconditioner was made where the path ended, far from the bracket (10 mm
  // against 0.3 mm on the 1e5-unknown cap): its stale solves cost more than a fresh factor (60
  // GMRES products, 1.8 s of the search's 5.3 s there). The first trial starts without it.
  if (solves_ == 0) p.reset_solver_caches();
  const cont::NewtonSettings newton = path_newton_settings(setup);
  cont::Vector z = start_for(p, h);
  bool converged = false;
  const auto corrector = [&] {
    const cont::NewtonResult r = cont::solve_at(p, z, h, newton);
    ++solves_;
    iterations_ += r.iterations;
    return r.converged;
  };
  if (z.size() > 0) converged = corrector();
  if (!converged) {  // the bracket's start, as before the interpolated starts
    z = in_present_layout(solved_.front().z, p);
    if (z.size() == 0 || !corrector()) return false;
  }
  force = p.indenter_force(z);
  solved_.push_back({h, z, force, true});
  return true;
}

}  // namespace si
