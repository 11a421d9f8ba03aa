// in_present_layout (indentation_run.hpp): an earlier state of the problem in its present layout,
// for warm starts after the candidate set grew (io/force_travel.cpp, critical_points.cpp).
#include "analysis/indentation_run.hpp"

namespace si {

cont::Vector in_present_layout(const Eigen::VectorXd& old, const IndentationProblem& p) {
  const int nf = p.num_shell_unknowns(), nl = p.num_local_unknowns();
  const int nc_old = static_cast<int>(old.size()) - nf - nl;
  cont::Vector z = cont::Vector::Zero(p.size());
  if (nc_old < 0 || nf + nc_old + nl > p.size()) return {};
  z.head(nf + nc_old) = old.head(nf + nc_old);
  z.tail(nl) = old.tail(nl);
  return z;
}

}  // namespace si
