// A rigid flat support frame under the shell, the second contact body of the indentation problem
// (ASTM D7136 and D6264 fixtures, docs/case-file.md `fixture`): the plate rests on it and may lift
// off. Its candidates are the mesh nodes over the frame (model/fixture.hpp); candidate i's gap is
// the distance of its back-face point X + u + c d (c the back face's offset along the director,
// -t/2 about the mid-plane) from the frame's plane along the plane's unit normal n (pointing from
// the frame into the plate), the plane flush with the undeformed back face:
//     g_i = n . (X_i + u_i + c d_i) - n . (X_i + c D_i)           (contact/node_gap.hpp)
// One multiplier mu_i >= 0 per candidate, the frame's force on the plate along n (N), and one row
//     phi(mu_i, kappa g_i) = 0,
// the indenter's NCP function and stiffness scale (contact_rows.hpp): the same complementarity
// machinery, on a body that does not move with the depth (dF/dh = 0). Frictionless: the force on
// the node is mu_i G_i (a force along n and its moment about the mid-surface point). The rows sit
// on one node's dofs each (node_row.hpp): the Krylov solver condenses them like the nodal gaps'.
#pragma once

#include <utility>
#include <vector>

#include "contact/ncp_function.hpp"
#include "indentation/contact_term.hpp"
#include "indentation/node_row.hpp"
#include "indentation/shell_part.hpp"

namespace si {

struct SupportFrameSetting {
  const ShellPart& shell;
  std::vector<int> nodes;  // mesh nodes over the frame: the candidates, less those held along n
  double face_offset = 0;  // c of the supported (back) face along the director, mm
  double kappa = 1;        // N/mm
  NcpFunction ncp = NcpFunction::kFischerBurmeisterMin;
};

class SupportFrame final : public ContactTerm {
 public:
  // The frame's normal is the candidates' common director; throws an input error naming `fixture`
  // if they do not share one (the frame supports a flat plate) or if there are none.
  explicit SupportFrame(SupportFrameSetting setting);

  int size() const override { return static_cast<int>(setting_.nodes.size()); }
  const std::vector<int>& candidates() const { return setting_.nodes; }
  const Vector3d& normal() const { return normal_; }

  void add_pattern(Triplets& t) const override;
  void locate(const SparseMatrix& J) override;
  void add_shell_force(const TermPoint& p, cont::Vector& r_free) override;
  void residual(const TermPoint& p, cont::Vector& F) override;
  void add_jacobian(const TermPoint& p, double* J,
                    std::vector<ContactJacobianRow>* condensed) override;
  bool condensable() const override { return true; }
  void signature(const TermPoint& p, std::vector<int>& out) const override;
  void active_gradients(const TermPoint& p, Triplets& out,
                        std::vector<int>& multiplier_index) const override;
  // The frame's whole-shell force (sum of mu_i times the symmetry factor) and bearing nodes.
  void quantities(const TermPoint& p, IndentationState& out) const override;
  // Per candidate: node, mu_i, g_i.
  void outputs(const TermPoint& p, IndentationState& out) const override;

  // Candidate i's gap (mm), with its gradient and, if asked, the gradient's derivative.
  NodeGap gap(int i, const TermPoint& p, bool derivative) const;

 private:
  // Strongly active: pressing beyond the roundoff of the largest multiplier (as contact_rows).
  bool bears(double mu, double mu_max) const { return mu > 1e-9 * mu_max && mu > 0; }

  SupportFrameSetting setting_;
  Vector3d normal_ = Vector3d::UnitZ();
  std::vector<NodeContactGeometry> geometry_;  // per candidate
  std::vector<double> level_;                  // per candidate: n . (X + c D), mm
  std::vector<NodeRowSlots> slots_;
};

}  // namespace si
