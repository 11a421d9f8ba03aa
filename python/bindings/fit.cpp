// Curve fits of the generic fitting library (fitting/, docs/fitting.md) on NumPy arrays.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "core/error.hpp"
#include "fitting/builtin_models.hpp"
#include "fitting/curve_model.hpp"
#include "fitting/linear_fit.hpp"

namespace si::py {
namespace {

const std::vector<std::string> kModels{"power", "power-log", "hertz", "power-offset"};

fit::FitResult fit_model(const std::string& model, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& y) {
  if (model == "power-log") return fit::fit_power_law_log(x, y);
  if (model == "power") return fit::fit_curve(fit::power_law(), x, y);
  if (model == "hertz") return fit::fit_curve(fit::hertz_law(), x, y);
  if (model == "power-offset") return fit::fit_curve(fit::power_law_with_offset(), x, y);
  throw_input("unknown model; expected power, power-log, hertz or power-offset",
              Where{"", "model", model, 0});
}

py::dict fit_curve(const std::string& model, const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  if (x.size() != y.size())
    throw_input("x and y differ in length (" + std::to_string(x.size()) + " and " +
                std::to_string(y.size()) + ")");
  fit::FitResult r;
  try {
    r = fit_model(model, x, y);
  } catch (const std::invalid_argument& e) {
    throw_input(e.what(), Where{"", "model", model, 0});
  }
  py::dict d;
  d["status"] = fit::to_string(r.status);
  d["reason"] = r.reason;
  d["method"] = r.method;
  d["names"] = r.names;
  d["parameters"] = r.parameters;
  d["std_errors"] = r.std_errors;
  d["ci_lower"] = r.ci_lower;
  d["ci_upper"] = r.ci_upper;
  d["confidence"] = r.confidence;
  d["covariance"] = r.covariance;
  d["num_points"] = r.num_points;
  d["r_squared"] = r.r_squared;
  d["rmse"] = r.rmse;
  d["residuals"] = r.residuals;
  d["fitted"] = r.fitted;
  return d;
}

}  // namespace

void bind_fit(py::module_& m) {
  m.attr("fit_models") = kModels;
  m.def("fit_curve", &fit_curve, py::arg("model"), py::arg("x"), py::arg("y"));
}

}  // namespace si::py
