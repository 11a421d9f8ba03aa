// The onset of geometric nonlinearity's watch (critical_points.hpp): during a run it keeps the
// states on both sides of the first point whose force departs from the linear-kinematics force
// by the fraction; after the run it solves the run's problem at the onset search's trial depths,
// each from the states it already has (issue 19 item 3: no wasted solves).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "analysis/indentation_run.hpp"
#include "indentation/linear_indentation.hpp"

namespace si {

class OnsetWatch {
 public:
  // Holds the case's linear-kinematics twin (its own mesh, model and factor).
  explicit OnsetWatch(const IndentationSetup& setup);

  // T_lin(h), N: the twin's force at depth h (mm), by the linear fast path.
  double linear_force(double h);

  // The twin's state at depth h in the layout of the run's problem p, while the watch has not
  // crossed: the run's first step starts from it (IndentationProblem::set_first_step_start).
  // Empty if the two do not share their unknowns (the run's candidates have grown).
  cont::Vector linear_state(double h, const IndentationProblem& p);

  // Feeds a converged point of the run and its state z. The watch keeps a bracket only from the
  // path's start (index 0) on: fed a later point first (a resumed run), it keeps none. Once it
  // has crossed (or stopped watching) the twin's factor is freed for the rest of the run: the
  // search after it refactors only if a trial depth's contact set needs a new S column.
  void add(const PathPoint& p, const cont::Vector& z);

  // The run's force at depth h inside the bracket that starts at depth `from`, solved by
  // `setup`'s corrector. The Newton start is the linear interpolation in depth of the two solved
  // states nearest h on either side (the bracket's ends, then each trial solved): the start's
  // error is O(dh^2) of the shrinking bracket instead of O(dh) from its start, so the trials
  // near the root take one or two iterations. A depth solved before is not solved again. False
  // if the bracket was not kept (the run never crossed, or `from` is not its start) or the
  // corrector fails from both the interpolated start and the bracket's start.
  bool solve_force(IndentationSetup& setup, double from, double h, double& force);

  // The bracket [from, to] (mm) once the run has crossed the fraction; none before.
  std::optional<std::pair<double, double>> bracket() const;
  int trial_solves() const { return solves_; }          // corrector runs so far (tests, benchmarks)
  int trial_iterations() const { return iterations_; }  // their Newton iterations
  int linear_solves() const { return linear_solves_; }  // linear_force() calls so far
  bool holds_twin_factor() const { return fast_.holds_factor(); }  // (tests)

 private:
  struct Solved {
    double depth = 0;
    cont::Vector z;  // in the layout of the problem when it was solved
    double force = 0;
    bool trial = false;  // solved after the run (its force is the run's own corrector's)
  };
  cont::Vector start_for(const IndentationProblem& p, double h) const;
  void stop_watching();

  IndentationSetup twin_;
  LinearIndentation fast_;
  double fraction_;
  bool crossed_ = false;
  bool passing_ = true;
  double last_depth_ = 0;
  cont::Vector last_z_;
  std::vector<Solved> solved_;  // the bracket's ends, then the trials
  int solves_ = 0;
  int iterations_ = 0;
  int linear_solves_ = 0;
};

}  // namespace si
