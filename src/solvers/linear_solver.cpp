#include "solvers/linear_solver.hpp"

#include <sstream>

#include "core/error.hpp"
#include "solvers/cholmod_solver.hpp"
#include "solvers/klu_solver.hpp"
#include "solvers/umfpack_solver.hpp"

namespace si {

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  if (name == "cholmod") return std::make_unique<CholmodSolver>();
  if (name == "umfpack") return std::make_unique<UmfpackSolver>();
  if (name == "klu") return std::make_unique<KluSolver>();
  throw_input("unknown linear solver (expected cholmod, umfpack or klu)",
              Where{"", "linear_solver", name, 0});
}

std::string singular_matrix_message(const std::string& solver, double rcond) {
  std::ostringstream os;
  os << "stiffness matrix is singular (" << solver << ", pivot ratio " << rcond
     << "): the model may be insufficiently supported (free rigid-body motion)";
  return os.str();
}

}  // namespace si
