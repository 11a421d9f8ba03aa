#include "indentation/weighted_gaps.hpp"

#include <utility>

#include "core/error.hpp"

namespace si {

WeightedGaps::WeightedGaps(const ContactRowsSetting& setting, InterpolatedContactOptions options)
    : ContactRows(setting), options_(std::move(options)) {
  SI_REQUIRE(!shell().nonlinear(),
             "the interpolated contact traction is defined for linear kinematics only");
}

void WeightedGaps::candidates_changed(bool) {
  const ShellModel& model = shell().model();
  const InterpolatedContact ic =
      integrate_interpolated_contact(model.mesh, shell().assembler(), *model.element,
                                     ContactFace{body().indenter(), body().direction(),
                                                 body().face_offset(), body().first_touch()},
                                     candidates_, options_);
  const Eigen::VectorXd inverse = ic.w.cwiseInverse();
  C_ = inverse.asDiagonal() * ic.C;
  C_.makeCompressed();
  g0_ = inverse.cwiseProduct(ic.g0);
  w_ = ic.w;
}

void WeightedGaps::add_pattern(Triplets& t) const {
  ContactRows::add_pattern(t);
  for (int i = 0; i < size(); ++i)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(C_, i); it; ++it) {
      t.emplace_back(static_cast<int>(it.col()), first() + i, 0.0);
      t.emplace_back(first() + i, static_cast<int>(it.col()), 0.0);
    }
}

void WeightedGaps::locate(const SparseMatrix& J) {
  ContactRows::locate(J);
  column_.clear();
  row_.clear();
  for (int i = 0; i < size(); ++i)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(C_, i); it; ++it) {
      column_.push_back(value_slot(J, static_cast<int>(it.col()), first() + i));
      row_.push_back(value_slot(J, first() + i, static_cast<int>(it.col())));
    }
}

double WeightedGaps::gap_value(int i, const TermPoint& p, double depth) const {
  return g0_[i] - depth + C_.row(i).dot(p.z.head(shell().size()));
}

void WeightedGaps::gradient(int i, const TermPoint&,
                            std::vector<std::pair<int, double>>& out) const {
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(C_, i); it; ++it)
    out.emplace_back(static_cast<int>(it.col()), it.value());
}

void WeightedGaps::add_shell_force(const TermPoint& p, cont::Vector& r_free) {
  r_free -= C_.transpose() * multipliers(p.z);
}

void WeightedGaps::add_jacobian(const TermPoint& p, double* J, std::vector<ContactJacobianRow>*) {
  prepare_layer(p);
  for (int k = 0; k < size(); ++k) {
    const double lambda = p.z[first() + k];
    const DentValue dent = dent_at(candidates_[k], p.z);
    const NcpValue phi = complementarity(lambda, contact_gap(k, p, p.h - dent.u));
    for (int e = C_.outerIndexPtr()[k]; e < C_.outerIndexPtr()[k + 1]; ++e) {
      J[column_[e]] -= C_.valuePtr()[e];
      J[row_[e]] += phi.d_b * kappa() * C_.valuePtr()[e];
    }
    add_multiplier_terms(k, phi, dent.rate, J);  // weighted gaps always reach the indenter
  }
}

SparseMatrix WeightedGaps::gap_matrix(const TermPoint&) const {
  return SparseMatrix(C_);
}

}  // namespace si
