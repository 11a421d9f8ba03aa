#include "io/calibration_spellings.hpp"

namespace si {

const Choices<fit::CalibrationAlgorithm>& calibration_algorithm_spellings() {
  static const Choices<fit::CalibrationAlgorithm> c{
      {"bobyqa", fit::CalibrationAlgorithm::kDerivativeFree},
      {"slsqp", fit::CalibrationAlgorithm::kGradient}};
  return c;
}

}  // namespace si
