// A thin-layer local contact (contact.local: vam; contact/local_contact_law.hpp, vam.md 7.3-7.4)
// as a part of the indentation problem: each candidate's gap gains c_L lambda_i / A_i, A_i the
// node's tributary area, the approach of its face under the pressure lambda_i / A_i. Linear and
// local to each row: no unknown of its own, and the Krylov solver and the linear fast path
// carry it (on the rows' diagonal).
#pragma once

#include <vector>

#include "indentation/contact_rows.hpp"
#include "indentation/local_approach.hpp"

namespace si {

class ThinLayer final : public ContactTerm, public LocalApproach {
 public:
  // compliance: c_L++ (mm/MPa). Keeps references to the shell and the rows.
  ThinLayer(double compliance, const ShellPart& shell, const ContactRows& rows);

  int size() const override { return 0; }
  void add_pattern(Triplets&) const override {}
  void locate(const SparseMatrix&) override {}
  void residual(const TermPoint&, cont::Vector&) override {}
  void add_jacobian(const TermPoint&, double*, std::vector<ContactJacobianRow>*) override {}
  bool condensable() const override { return true; }  // on the rows' diagonal, no rows of its own
  // The approach at the apex node and the energy sum_i 1/2 c_L lambda_i^2 / A_i (whole shell).
  void outputs(const TermPoint& p, IndentationState& out) const override;

  double layer(const std::vector<int>& nodes, int i,
               const Eigen::Ref<const cont::Vector>& lambda) const override;
  double layer_rate(int node) const override;

 private:
  double compliance_;
  const ShellPart& shell_;
  const ContactRows& rows_;
};

}  // namespace si
