// The paper's interpolated traction (contact.traction: interpolated; interpolated_contact.hpp),
// linear kinematics only: the traction is interpolated from nodal values t-bar_i and candidate
// i's gap is its weighted gap (with the F-bar coupling if asked). The unknowns stay nodal forces,
// lambda_i = t-bar_i w_i (N), and the gap of row i is the weighted gap over its weight,
//     g_i = (g~0_i - h w_i + C~_i x) / w_i   (mm),
// a positive scaling of the paper's rows that leaves the solution, t-bar = lambda / w, unchanged
// and lets kappa, the force scale and the fast path apply as they are. A row spans the dofs of
// its node's elements: no condensation, the problem uses a direct LU.
#pragma once

#include <vector>

#include "indentation/contact_rows.hpp"
#include "indentation/interpolated_contact.hpp"

namespace si {

class WeightedGaps final : public ContactRows {
 public:
  // Throws unless the shell's kinematics are linear.
  WeightedGaps(const ContactRowsSetting& setting, InterpolatedContactOptions options);

  void add_pattern(Triplets& t) const override;
  void locate(const SparseMatrix& J) override;
  void add_shell_force(const TermPoint& p, cont::Vector& r_free) override;
  void add_jacobian(const TermPoint& p, double* J,
                    std::vector<ContactJacobianRow>* condensed) override;
  SparseMatrix gap_matrix(const TermPoint& reference) const override;

 private:
  double gap_value(int i, const TermPoint& p, double depth) const override;
  bool hits(int, const TermPoint&, double) const override { return true; }
  void gradient(int i, const TermPoint& p, std::vector<std::pair<int, double>>& out) const override;
  double pressure_area(int i) const override { return w_[i]; }
  // Integrates the weighted gaps of the candidates (interpolated_contact.hpp).
  void candidates_changed(bool appended) override;

  InterpolatedContactOptions options_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> C_;  // C~_i / w_i, candidates x free dofs
  Eigen::VectorXd g0_;                              // g~0_i / w_i, mm
  Eigen::VectorXd w_;                               // w_i, mm^2
  std::vector<int> column_;                         // per entry (i, j): slot of (j, multiplier i)
  std::vector<int> row_;                            // per entry (i, j): slot of (multiplier i, j)
};

}  // namespace si
