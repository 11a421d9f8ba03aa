// Restarted GMRES with right preconditioning (Saad & Schultz 1986; Saad, "Iterative Methods for
// Sparse Linear Systems", 2nd ed., Alg. 9.5): solves A x = b given only y -> A y and the
// preconditioner z -> M^-1 z. Right preconditioning keeps the true residual b - A x as the
// quantity that is minimised and tested, whatever the preconditioner.
#pragma once

#include <functional>

#include <Eigen/Core>

namespace si {

struct GmresSettings {
  double relative_tolerance = 1e-12;  // ||b - A x||_2 <= tol ||b||_2
  int restart = 30;                   // Krylov vectors kept before a restart
  int max_iterations = 60;            // matrix-vector products in all
};

struct GmresResult {
  bool converged = false;
  int iterations = 0;              // matrix-vector products
  double relative_residual = 0.0;  // ||b - A x|| / ||b|| at the end
};

using LinearOperator = std::function<void(const Eigen::VectorXd& in, Eigen::VectorXd& out)>;

// x holds the starting guess on entry (zero is fine) and the solution on exit.
GmresResult gmres(const LinearOperator& apply_a, const LinearOperator& apply_m_inverse,
                  const Eigen::VectorXd& b, Eigen::VectorXd& x, const GmresSettings& settings);

}  // namespace si
