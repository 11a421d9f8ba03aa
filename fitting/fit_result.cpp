#include "fitting/fit_result.hpp"

namespace si::fit {

const char* to_string(FitStatus status) {
  switch (status) {
    case FitStatus::kConverged:
      return "converged";
    case FitStatus::kStalled:
      return "stalled";
    case FitStatus::kFailed:
      return "failed";
  }
  return "failed";
}

}  // namespace si::fit
