// A curve y = f(x; c) to fit to points (x_i, y_i): its value, optionally its gradient df/dc
// (finite differences otherwise), and optionally a rule for starting values from the data.
// curve_problem() turns it into the least-squares problem r_i = f(x_i; c) - y_i.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "fitting/fit_result.hpp"
#include "fitting/least_squares_problem.hpp"
#include "fitting/nonlinear_fit.hpp"

namespace si::fit {

struct CurveModel {
  std::string name;     // e.g. "power"
  std::string formula;  // e.g. "y = C1 * x^C2"
  std::vector<std::string> parameter_names;
  std::function<double(double x, const Eigen::VectorXd& c)> value;  // required
  // Optional: fills grad (size = number of parameters) with df/dc_j at x.
  std::function<void(double x, const Eigen::VectorXd& c, Eigen::Ref<Eigen::VectorXd> grad)>
      gradient;
  // Optional: starting values guessed from the data.
  std::function<Eigen::VectorXd(const Eigen::VectorXd& x, const Eigen::VectorXd& y)> start;
  double min_x = -std::numeric_limits<double>::infinity();  // the model is defined for x >= min_x
};

// The data are copied into the problem, which therefore outlives the arguments.
LeastSquaresProblem curve_problem(const CurveModel& model, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd& y);

// Fits the model; empty settings.start means the model's own guess (or all ones without one).
// Throws std::invalid_argument for x outside the model's domain or sizes that disagree.
FitResult fit_curve(const CurveModel& model, const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                    FitSettings settings = {});

}  // namespace si::fit
