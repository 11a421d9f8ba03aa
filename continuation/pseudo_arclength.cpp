#include "continuation/pseudo_arclength.hpp"

#include "continuation/arclength_stepper.hpp"

namespace si::cont {

Branch pseudo_arclength(Problem& problem, Vector x0, double p0, const Settings& settings,
                        const Callback& callback) {
  BorderedSolver bordered(problem, settings.parameter_weight);
  ArclengthStepper stepper(problem, bordered, settings);
  return trace(problem, stepper, bordered,
               {x0, p0, Vector(), static_cast<double>(settings.direction), 0}, settings, callback,
               std::nullopt);
}

Branch pseudo_arclength(Problem& problem, const Checkpoint& resume, const Settings& settings,
                        const Callback& callback) {
  BorderedSolver bordered(problem, settings.parameter_weight);
  ArclengthStepper stepper(problem, bordered, settings);
  return trace(problem, stepper, bordered, Start{}, settings, callback, resume);
}

}  // namespace si::cont
