// A part of the state computed from the shell's displacement field and the contact pressures,
// beyond what the problem's own parts report: the failure indices near the indenter of a run that
// monitors damage (analysis/damage_probe.hpp). The runs set it (IndentationOptions::probe); the
// problem calls it wherever it computes the monitors' quantities, off the branch too, so it must
// be a function of the point alone.
#pragma once

#include <vector>

#include "core/linalg.hpp"
#include "indentation/indentation_state.hpp"
#include "shell/director.hpp"

namespace si {

struct ProbePoint {
  const std::vector<NodeState>& states;  // every mesh node
  const std::vector<int>& candidates;    // mesh nodes of the contact candidates
  const Eigen::VectorXd& pressures;      // contact pressure per candidate, MPa (>= 0 in contact)
  const Eigen::VectorXd& forces;         // contact force (multiplier) per candidate, N
  double force;                          // the indenter's contact force, whole shell, N
};

class StateProbe {
 public:
  virtual ~StateProbe() = default;
  virtual void measure(const ProbePoint& point, IndentationState& out) const = 0;
};

}  // namespace si
