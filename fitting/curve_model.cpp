#include "fitting/curve_model.hpp"

#include <stdexcept>

namespace si::fit {

LeastSquaresProblem curve_problem(const CurveModel& model, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd& y) {
  if (x.size() != y.size()) throw std::invalid_argument("x and y differ in length");
  if (!model.value) throw std::invalid_argument("curve model '" + model.name + "' has no value");
  LeastSquaresProblem p;
  p.num_residuals = static_cast<int>(x.size());
  p.parameter_names = model.parameter_names;
  p.observed = y;
  const auto value = model.value;
  p.residuals = [value, x, y](const Eigen::VectorXd& c, Eigen::VectorXd& r) {
    for (Eigen::Index i = 0; i < x.size(); ++i) r[i] = value(x[i], c) - y[i];
  };
  if (model.gradient) {
    const auto gradient = model.gradient;
    p.jacobian = [gradient, x](const Eigen::VectorXd& c, Eigen::MatrixXd& jac) {
      Eigen::VectorXd g(c.size());
      for (Eigen::Index i = 0; i < x.size(); ++i) {
        gradient(x[i], c, g);
        jac.row(i) = g.transpose();
      }
    };
  }
  return p;
}

FitResult fit_curve(const CurveModel& model, const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                    FitSettings settings) {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!(x[i] >= model.min_x))
      throw std::invalid_argument("model '" + model.name +
                                  "' needs x >= " + std::to_string(model.min_x) + ", point " +
                                  std::to_string(i + 1) + " has x = " + std::to_string(x[i]));
  const LeastSquaresProblem problem = curve_problem(model, x, y);
  if (settings.start.size() == 0)
    settings.start =
        model.start ? model.start(x, y) : Eigen::VectorXd::Ones(problem.num_parameters()).eval();
  return fit(problem, settings);
}

}  // namespace si::fit
