// A power-law local contact (contact.local: hertz | yang_sun; contact/local_contact_law.hpp,
// docs/theory/local-indentation.md) as a part of the indentation problem: one more unknown, the
// local approach alpha (mm) of the indenter towards the shell's contact face, and its row
//     s sum_i lambda_i - k sgn(alpha) |alpha|^1.5 = 0     (s = symmetry factor: the law holds
//                                                          for the whole shell)
// written as force in terms of alpha (not alpha = (F/k)^(2/3), whose derivative is infinite at
// F = 0): its derivative 1.5 k alpha^0.5 is finite everywhere and zero at the start, where the
// alpha column still has d_b kappa du/dalpha = d_b kappa in the row of the first-touch node (its
// r is 0: inside the patch), so the Jacobian stays regular (local-indentation.md 3). The contact
// face is dented by Hertz's profile u_i = u(r_i; alpha) of the law (hertz_dent.hpp; alpha at the
// axis, r_i the node's distance from the indenter's axis in the reference configuration), so the
// indenter's travel into node i's face is h - u_i: a flat punch at depth h - alpha inside the
// patch r <= (R alpha)^0.5, the half-space's surface displacement outside. The contact rows see
// the dent through the LocalApproach interface. Nonlinear: the linear fast path refuses it.
#pragma once

#include <optional>
#include <vector>

#include "contact/local_contact_law.hpp"
#include "indentation/contact_rows.hpp"
#include "indentation/local_approach.hpp"

namespace si {

class PowerLawApproach final : public ContactTerm, public LocalApproach {
 public:
  // Keeps references to the body and the rows whose multipliers it sums.
  PowerLawApproach(const LocalContactLaw& law, const ContactBody& body, const ContactRows& rows,
                   double symmetry_factor);

  int size() const override { return 1; }
  void add_pattern(Triplets& t) const override;
  void locate(const SparseMatrix& J) override;
  void residual(const TermPoint& p, cont::Vector& F) override;
  void add_jacobian(const TermPoint& p, double* J,
                    std::vector<ContactJacobianRow>* condensed) override;
  // The local approach alpha (mm) and the energy (2/5) k alpha^2.5 (N mm).
  void outputs(const TermPoint& p, IndentationState& out) const override;

  DentValue dent(int node, const cont::Vector& z) const override;
  int alpha_index() const override { return first(); }
  bool regularizes_touch() const override { return true; }
  bool borders() const override { return true; }

 private:
  LocalContactLaw law_;
  const ContactRows& rows_;
  double symmetry_factor_;
  std::vector<double> dent_radius_;  // per mesh node: r of the dent profile, mm
  // The dent at the last alpha: every candidate's gap at an iterate shares it (a finite-thickness
  // law's contact radius and table slice are found once per alpha).
  mutable std::optional<DentProfile> dent_profile_;
  std::vector<int> row_slots_;  // (alpha, multiplier i)
  int diagonal_ = -1;           // (alpha, alpha)
};

}  // namespace si
