// NLopt's return codes in words, and which of them are failures, shared by the curve fitter and
// the calibration (NLopt 2.7.1, nlopt.h: positive codes are successful stops, negative ones
// errors; the C++ interface throws for the negative ones, run_nlopt() turns them back into codes).
#pragma once

#include <nlopt.hpp>

#include <string>
#include <vector>

namespace si::fit {

// "SUCCESS", "FTOL_REACHED", ..., "FAILURE", "ROUNDOFF_LIMITED", "FORCED_STOP".
std::string nlopt_code_name(int code);

// "LD_SLSQP", "LN_BOBYQA", ... (NLopt's enumerator without the NLOPT_ prefix).
std::string nlopt_algorithm_name(nlopt::algorithm algorithm);

// A negative code: NLopt did not finish its own search (FAILURE, INVALID_ARGS, OUT_OF_MEMORY,
// ROUNDOFF_LIMITED, FORCED_STOP).
inline bool is_nlopt_failure(int code) {
  return code < 0;
}

// Runs `opt` from `x` (updated in place) and returns NLopt's code, the negative codes included
// instead of thrown (nlopt::opt::optimize throws for them). NLopt keeps no best point across
// an exception, so the objective should remember its best evaluation itself.
int optimize_returning_code(nlopt::opt& opt, std::vector<double>& x, double& f);

}  // namespace si::fit
