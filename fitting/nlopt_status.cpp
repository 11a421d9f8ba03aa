#include "fitting/nlopt_status.hpp"

#include <stdexcept>

namespace si::fit {

std::string nlopt_code_name(int code) {
  switch (code) {
    case nlopt::SUCCESS:
      return "SUCCESS";
    case nlopt::STOPVAL_REACHED:
      return "STOPVAL_REACHED";
    case nlopt::FTOL_REACHED:
      return "FTOL_REACHED";
    case nlopt::XTOL_REACHED:
      return "XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED:
      return "MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED:
      return "MAXTIME_REACHED";
    case nlopt::FAILURE:
      return "FAILURE";
    case nlopt::INVALID_ARGS:
      return "INVALID_ARGS";
    case nlopt::OUT_OF_MEMORY:
      return "OUT_OF_MEMORY";
    case nlopt::ROUNDOFF_LIMITED:
      return "ROUNDOFF_LIMITED";
    case nlopt::FORCED_STOP:
      return "FORCED_STOP";
    default:
      return "code " + std::to_string(code);
  }
}

std::string nlopt_algorithm_name(nlopt::algorithm algorithm) {
  switch (algorithm) {
    case nlopt::LD_SLSQP:
      return "LD_SLSQP";
    case nlopt::LD_LBFGS:
      return "LD_LBFGS";
    case nlopt::LN_BOBYQA:
      return "LN_BOBYQA";
    default:
      return nlopt::algorithm_name(algorithm);
  }
}

int optimize_returning_code(nlopt::opt& opt, std::vector<double>& x, double& f) {
  try {
    return static_cast<int>(opt.optimize(x, f));
  } catch (const nlopt::roundoff_limited&) {
    return nlopt::ROUNDOFF_LIMITED;
  } catch (const nlopt::forced_stop&) {
    return nlopt::FORCED_STOP;
  } catch (const std::invalid_argument&) {
    return nlopt::INVALID_ARGS;
  } catch (const std::bad_alloc&) {
    return nlopt::OUT_OF_MEMORY;
  } catch (const std::runtime_error&) {
    return nlopt::FAILURE;
  }
}

}  // namespace si::fit
