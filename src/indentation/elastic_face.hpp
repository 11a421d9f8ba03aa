// The elastic face (`local_support: shell`, contact/face_influence.hpp) as a part of the
// indentation problem: candidate i's gap gains the face's approach sum_j C_ij lambda_j, with
// C_ij the influence coefficient between the reference face points of nodes i and j, summed over
// the mirror images of j in the model's symmetry planes (a quarter model's multiplier stands for
// the same force at each image), and a node on itself (or on an image of itself) the centre of
// a disc of its physical tributary area. C is symmetric; with the shell's compliance it is the
// face's, positive definite.
//
// Linear in the multipliers with no unknown of its own: the linear fast path adds C's columns to
// the Schur complement (linear_indentation.hpp); the Newton paths' rows gain C's entries in the
// other multipliers' columns (coupling_members(), coupling_column()), a dense block over the zone
// kept beside J's pattern (row_coupling.hpp), which the Krylov solver's preconditioner eliminates
// over the pressed rows (coupled_rows.hpp). The zone:
// the candidates within a radius of the first touch's face point. Outside it a node's approach is
// its own disc's alone: C_ij = 0 for i != j unless both lie in the zone, so that the Newton paths
// and the fast path solve one model wherever the contact stays in the zone. The zone follows the
// contact: it starts at a quarter of its bound (`zone_bound`, which the runs make the sphere's
// chord at the path's depth, an upper bound of the contact radius), and after an accepted point
// whose pressed nodes reach past kZoneFill of it, it widens to kZoneGrowth times their reach (at
// most to the bound) and the point is solved again (adapt()): every accepted point has its contact
// inside the zone. Why: the block's entries go as the zone's radius to the fourth power, and they
// fill the GMRES products (a whole-path zone made J twice the shell's size on the paper's cap
// 0-10 mm, when the block was in J's pattern). The runs give the fast path zone_bound -1: every
// pair coupled and no block (it needs none, and a 0-10 mm zone on a fine mesh is 1e8 entries);
// zone_bound 0 couples every pair on the Newton paths too (the tests' small models). The
// coefficients are those of the reference configuration (the face's kernel is a small-strain one;
// with nonlinear kinematics the contact patch stays small against the cap).
#pragma once

#include <memory>
#include <vector>

#include "contact/face_influence.hpp"
#include "indentation/contact_body.hpp"
#include "indentation/contact_rows.hpp"
#include "indentation/local_approach.hpp"

namespace si {

class ElasticFace final : public ContactTerm, public LocalApproach {
 public:
  static constexpr int kMaxZoneNodes = 3000;  // 9e6 block entries (72 MB of C)
  // The zone widens once its pressed nodes reach past this share of its radius, to this factor
  // times their reach: a few widenings over a path, each a re-solve. Widening to 1.5 times the
  // zone instead (1.9 times the reach) took the 0.25 mm quarter cap's zone to 11.9 mm when the
  // contact reached 6.5 mm, for the rest of a 0-10 mm path (entries go as the radius^4): 35-37 s
  // against 28-29 s now (`none` 24 s, paired); the 0.5 mm quarter cap 0-2 mm, with more
  // widenings, costs 1.32-1.37 s against 1.27-1.29 s (`none` 1.21 s).
  static constexpr double kZoneFill = 0.8;
  static constexpr double kZoneGrowth = 1.5;
  // The influence table reaches the largest distance between the body's reachable nodes and
  // their images. zone_bound < 0: every pair coupled and no Newton block (the linear fast path
  // only). Throws an input error naming contact.local_support if the bound's zone holds more
  // than kMaxZoneNodes reachable nodes (the block's memory, n^2 entries). Keeps references to
  // the shell, the body and the rows.
  ElasticFace(std::shared_ptr<const SupportKernel> kernel, const ShellPart& shell,
              const ContactBody& body, const ContactRows& rows, double zone_bound = 0);

  int size() const override { return 0; }
  void add_pattern(Triplets&) const override {}
  void locate(const SparseMatrix&) override {}
  void residual(const TermPoint&, cont::Vector&) override {}
  void add_jacobian(const TermPoint&, double*, std::vector<ContactJacobianRow>*) override {}
  // No rows of its own; the rows' couplings are eliminated by the preconditioner
  // (coupled_rows.hpp).
  bool condensable() const override { return true; }
  // The approach at the apex node, the energy 1/2 lambda^T C lambda (whole shell) and the apex's
  // mid-plane share sum_j M_apex,j lambda_j (M: the mid-plane kernel's coefficients).
  void outputs(const TermPoint& p, IndentationState& out) const override;

  // u = C lambda over the candidates, once per sweep (from C's columns of the pressed nodes).
  void prepare(const std::vector<int>& nodes,
               const Eigen::Ref<const cont::Vector>& lambda) const override;
  // u_i as prepared for these multipliers (by their storage), else computed for row i alone.
  double layer(const std::vector<int>& nodes, int i,
               const Eigen::Ref<const cont::Vector>& lambda) const override;
  double layer_rate(int node) const override { return coefficient(node, node); }
  void add_compliance_column(const std::vector<int>& nodes, int j,
                             Eigen::VectorXd& column) const override;
  // The zone's members (every candidate with zone_bound 0; none with zone_bound < 0) and C's
  // columns (kept: the ones prepare() uses).
  std::vector<int> coupling_members(const std::vector<int>& nodes) const override;
  const Eigen::VectorXd& coupling_column(const std::vector<int>& nodes, int j) const override {
    return column(nodes, j);
  }
  bool adapt(const std::vector<int>& nodes, const Eigen::Ref<const cont::Vector>& lambda) override;
  // The zone's radius (mm) where it follows the contact, else nothing.
  std::vector<double> adapted() const override;
  bool restore_adapted(const std::vector<double>& values) override;

  // C between mesh nodes a and b, mm/N (0 for a != b unless both lie in the zone).
  double coefficient(int a, int b) const {
    return a == b ? own(a) : coefficient(*influence_, a, b);
  }
  bool in_zone(int node) const;

 private:
  struct Mirror {
    int axis = 0;
    double at = 0;  // the plane x_axis = at
  };
  // The images of point x in the symmetry planes, x itself first.
  std::vector<Vector3d> images(const Vector3d& x) const;
  double coefficient(const FaceInfluence& kernel, int a, int b) const;
  // C_aa, computed on first use and kept: every Newton row's diagonal asks for it (its disc is a
  // quadrature of the transform).
  double own(int node) const;
  // C's column j over `nodes`, computed on first use and kept (the pressed nodes' columns: as
  // many as the fast path keeps of S), after keep_columns_of(nodes), which drops them (and the
  // zone's members among the candidates) when the candidates change.
  void keep_columns_of(const std::vector<int>& nodes) const;
  // A new zone radius; the kept columns and zone members go with the old one.
  void set_zone(double radius);
  const Eigen::VectorXd& column(const std::vector<int>& nodes, int j) const;

  const ShellPart& shell_;
  const ContactBody& body_;
  const ContactRows& rows_;
  std::vector<Mirror> mirrors_;
  double zone_bound_ = 0, zone_radius_ = 0;
  std::unique_ptr<FaceInfluence> influence_;
  std::unique_ptr<FaceInfluence> mid_plane_;  // the same for the mid-plane (PlateSurface::kMid)
  mutable std::vector<double> own_;           // per mesh node, NaN until asked
  mutable std::vector<int> column_nodes_;
  mutable std::vector<Eigen::VectorXd> columns_;
  mutable std::vector<int> zone_members_;  // the candidates (indices) in the zone
  mutable Eigen::VectorXd approach_;       // u = C lambda of the last prepare()
  mutable const double* prepared_for_ = nullptr;
};

}  // namespace si
