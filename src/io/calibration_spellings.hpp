// The command line's spellings of the calibration's enums (`shellindent calibrate --algorithm`),
// beside io/spellings.hpp's case-file ones: kept apart so that the case-file reader (and its
// fuzz harness, tests/fuzz/sources.cmake) does not depend on the fitting library.
#pragma once

#include "fitting/calibration.hpp"
#include "io/yaml_reader.hpp"

namespace si {

// bobyqa (derivative-free, LN_BOBYQA), slsqp (gradient by finite differences, LD_SLSQP).
const Choices<fit::CalibrationAlgorithm>& calibration_algorithm_spellings();

}  // namespace si
