#include "continuation/settings.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace si::cont {
namespace {

std::string str(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// "<prefix>.<field> = <value> <what>"
void require_field(bool ok, const std::string& prefix, const std::string& field, double value,
                   const std::string& what) {
  require(ok, prefix + "." + field + " = " + str(value) + " " + what);
}

void require_positive(const std::string& prefix, const std::string& field, double value) {
  require_field(std::isfinite(value) && value > 0.0, prefix, field, value,
                "must be positive and finite");
}

}  // namespace

void NewtonSettings::validate(const std::string& prefix) const {
  require_field(
      std::isfinite(relative_tolerance) && relative_tolerance > 0.0 && relative_tolerance < 1.0,
      prefix, "relative_tolerance", relative_tolerance, "must lie in (0, 1)");
  require_field(std::isfinite(residual_scale) && residual_scale >= 0.0, prefix, "residual_scale",
                residual_scale, "must be >= 0 and finite");
  require_field(max_iterations >= 1, prefix, "max_iterations", max_iterations, "must be >= 1");
  require_field(std::isfinite(max_step) && max_step >= 0.0, prefix, "max_step", max_step,
                "must be >= 0 (0 = automatic)");
  require_field(stall_window >= 0, prefix, "stall_window", stall_window,
                "must be >= 0 (0 = never give up early)");
  require_field(std::isfinite(stall_ratio) && stall_ratio > 0.0 && stall_ratio < 1.0, prefix,
                "stall_ratio", stall_ratio, "must lie in (0, 1)");
}

Method parse_method(const std::string& name) {
  if (name == "natural") return Method::kNatural;
  if (name == "pseudo_arclength") return Method::kPseudoArclength;
  throw std::invalid_argument("continuation.method = '" + name +
                              "' is unknown (expected natural | pseudo_arclength)");
}

std::string method_name(Method method) {
  return method == Method::kNatural ? "natural" : "pseudo_arclength";
}

Predictor parse_predictor(const std::string& name) {
  if (name == "tangent") return Predictor::kTangent;
  if (name == "secant") return Predictor::kSecant;
  throw std::invalid_argument("continuation.predictor = '" + name +
                              "' is unknown (expected tangent | secant)");
}

std::string predictor_name(Predictor predictor) {
  return predictor == Predictor::kTangent ? "tangent" : "secant";
}

void Settings::validate() const {
  const std::string c = "continuation";
  require(method == Method::kNatural || method == Method::kPseudoArclength,
          c + ".method = " + std::to_string(static_cast<int>(method)) + " is unknown");
  require(predictor == Predictor::kTangent || predictor == Predictor::kSecant,
          c + ".predictor = " + std::to_string(static_cast<int>(predictor)) + " is unknown");
  require_field(direction == 1 || direction == -1, c, "direction", direction, "must be +1 or -1");
  require_positive(c, "step_min", step_min);
  require_positive(c, "step_max", step_max);
  require_positive(c, "step_initial", step_initial);
  require(step_min <= step_max,
          c + ".step_min = " + str(step_min) + " > step_max = " + str(step_max));
  require(step_min <= step_initial && step_initial <= step_max,
          c + ".step_initial = " + str(step_initial) + " is outside [step_min, step_max] = [" +
              str(step_min) + ", " + str(step_max) + "]");
  require_field(target_iterations >= 1, c, "target_iterations", target_iterations, "must be >= 1");
  require_field(std::isfinite(step_growth_max) && step_growth_max >= 1.0, c, "step_growth_max",
                step_growth_max, "must be >= 1");
  require_field(landing_stretch >= 0.0 && landing_stretch <= 1.0, c, "landing_stretch",
                landing_stretch, "must lie in [0, 1]");
  require_field(max_turn_deg > 0.0 && max_turn_deg < 180.0, c, "max_turn_deg", max_turn_deg,
                "must lie in (0, 180)");
  require(!std::isnan(p_min) && !std::isnan(p_max) && p_min < p_max,
          c + ".p_min = " + str(p_min) + " must be < p_max = " + str(p_max));
  require_field(max_steps >= 0, c, "max_steps", max_steps, "must be >= 0");
  require_positive(c, "parameter_weight", parameter_weight);
  require_field(natural_corrector_slope >= 0.0 && natural_corrector_slope < 1.0, c,
                "natural_corrector_slope", natural_corrector_slope, "must lie in [0, 1)");
  newton.validate(c + ".newton");
  require_field(newton.residual_scale > 0.0, c + ".newton", "residual_scale", newton.residual_scale,
                "must be positive for continuation (a purely relative tolerance collapses "
                "below roundoff as the predictor improves)");
  for (std::size_t i = 0; i < parameter_values.size(); ++i) {
    require(std::isfinite(parameter_values[i]), c + ".parameter_values[" + std::to_string(i) +
                                                    "] = " + str(parameter_values[i]) +
                                                    " must be finite");
    require(i == 0 || parameter_values[i] > parameter_values[i - 1],
            c + ".parameter_values[" + std::to_string(i) + "] = " + str(parameter_values[i]) +
                " must be greater than the previous value (strictly increasing)");
  }
  require_positive(c, "event_tolerance", event_tolerance);
  require_field(event_max_iterations >= 1, c, "event_max_iterations", event_max_iterations,
                "must be >= 1");
  require_positive(c, "feature_noise_factor", feature_noise_factor);
  require_field(std::isfinite(feature_curvature_tolerance) && feature_curvature_tolerance >= 0.0, c,
                "feature_curvature_tolerance", feature_curvature_tolerance,
                "must be >= 0 and finite");
  require_field(feature_refinement >= 1, c, "feature_refinement", feature_refinement,
                "must be >= 1");
  require_field(stability_modes >= 0, c, "stability_modes", stability_modes, "must be >= 0");
  for (const auto& pair : inflections)
    require(!pair.monitor.empty() && !pair.against.empty() && pair.monitor != pair.against,
            c + ".inflections: pair ('" + pair.monitor + "', '" + pair.against +
                "') needs two different monitor names");
  require_field(checkpoint_interval >= 0, c, "checkpoint_interval", checkpoint_interval,
                "must be >= 0");
  require(checkpoint_path.empty() || checkpoint_writer,
          c + ".checkpoint_path = '" + checkpoint_path + "' needs a checkpoint_writer");
  require(checkpoint_interval == 0 || !checkpoint_path.empty(),
          c + ".checkpoint_interval = " + std::to_string(checkpoint_interval) +
              " needs a checkpoint_path");
}

}  // namespace si::cont
