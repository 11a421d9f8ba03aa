#include "analysis/static_spec.hpp"

#include <string>

#include "core/decimal_number.hpp"
#include "core/error.hpp"

namespace si {
namespace {

void bad(const std::string& key, const std::string& value, const std::string& why) {
  throw_input(why, Where{"", "static." + key, value, 0});
}

}  // namespace

void StaticSettings::validate() const {
  if (steps < 1) bad("steps", std::to_string(steps), "need at least 1 load step");
  if (max_iterations < 1)
    bad("max_iterations", std::to_string(max_iterations), "need at least 1 Newton iteration");
  if (!(tolerance > 0 && tolerance < 1))
    bad("tolerance", format_decimal(tolerance), "tolerance must be in (0, 1)");
  if (max_halvings < 0 || max_halvings > 30)
    bad("max_halvings", std::to_string(max_halvings), "max_halvings must be in 0..30");
  if (linear_solver != LinearSolverKind::kCholmod && linear_solver != LinearSolverKind::kUmfpack)
    bad("linear_solver", make_linear_solver(linear_solver)->name(),
        "not a solver for the static run (expected cholmod or umfpack)");
  if (method != PathMethod::kPseudoArclength) return;
  if (!(step_min > 0 && step_min <= step && step <= step_max))
    bad("step", format_decimal(step), "need 0 < step_min <= step <= step_max");
  if (!(parameter_weight > 0))
    bad("parameter_weight", format_decimal(parameter_weight), "must be positive");
  if (!(load_factor_max > 0))
    bad("load_factor_max", format_decimal(load_factor_max), "must be positive");
  if (max_steps < 1) bad("max_steps", std::to_string(max_steps), "need at least 1 step");
}

}  // namespace si
