// The force a case predicts at given indenter travels: the one function through which a
// calibration (app/calibrate_command.hpp) reads path results, so that it can follow the solvers
// wherever they move.
//
// The case runs as `shellindent run` would, without writing anything, from first touch to the
// last travel asked for, stopping exactly at every travel: path.depth_max is set to the last
// travel, path.depths to the travels, and a continuation run uses the natural method in the
// depth (the linear fast path and the active-set grid stop at path.depths anyway). So each force
// is a converged point, a smooth function of the case's numbers. Not a pseudo-arclength branch
// read between its adaptive points: where a node enters contact between two points the force
// has a kink, cubic Hermite interpolation across it errs by up to 1 % (measured on a coarse cap,
// docs/calibration.md), and the points move with the parameters, so the misfit would jump by
// that much from one evaluation to the next. The price: a branch that folds back in the depth
// (snap-back) cannot be followed, and such a run is reported as a failure.
//
// Warm start: a calibration evaluates the same case many times with slightly different numbers.
// Given the converged states of an earlier run at the same travels (ForceTravelStates), each
// travel is solved directly from the earlier state (Newton at fixed depth, the path's own
// settings, the candidate set grown where contact spreads), without the path in between: on the
// default cap with the Yang-Sun law, 29 Newton iterations instead of 66 (1 % change of E3), the
// forces equal to the full run's to 1e-8 N. If any travel fails to converge that way, the full
// path is run instead.
//
// Travel is the path's depth: the indenter's travel along its direction after first touch. With
// contact.local it includes the local indentation (travel = shell deflection under the indenter
// + local approach), which is what a test machine's crosshead or an LVDT on the indenter measures.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "analysis/indentation_case.hpp"

namespace si {

// The converged states of a run at its travels (the solver's unknowns: shell, contact
// multipliers, local approach), and the contact candidate set and local law's adapted state
// (an elastic face's zone) they refer to.
struct ForceTravelStates {
  std::vector<int> candidates;
  std::vector<double> local_state;
  std::vector<Eigen::VectorXd> states;  // one per travel
  int num_shell = 0, num_local = 0;
};

struct ForceTravel {
  std::vector<double> force;  // N, whole-shell, one per travel
  bool ok = false;
  std::string failure;  // why not: the case cannot be built, or the path stops short
  bool warm = false;    // solved from the given states (else by the full path)
  int newton_iterations = 0;
  ForceTravelStates states;  // when ok: to warm-start a later run
};

// travels: mm, >= 0, strictly increasing, the last > 0. keep_going is asked after every
// converged point (false: stop, e.g. Ctrl-C). warm: states of an earlier run of the same case
// (other numbers) at the same travels, or null. Throws nothing for numerical or input trouble
// of the case: that is a failure in the result.
ForceTravel run_force_travel(IndentationCase c, const std::vector<double>& travels, int threads,
                             const std::function<bool()>& keep_going = {},
                             const ForceTravelStates* warm = nullptr);

}  // namespace si
