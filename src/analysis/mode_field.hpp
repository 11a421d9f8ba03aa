// A critical mode (a vector of a problem's shell unknowns in chart coordinates, e.g. a
// stability_change event's mode) as a nodal field for the VTU files.
#pragma once

#include <Eigen/Dense>

#include "model/dof_map.hpp"

namespace si {

// The mode's translations per node (rows = nodes; the chart's translation coordinates are the
// nodes' first three dofs, prescribed ones 0), scaled so that the largest is 1: a shape, whose
// sign is the eigen-solver's.
Eigen::MatrixXd mode_translations(const DofMap& dofs, const Eigen::VectorXd& mode, int nodes);

}  // namespace si
