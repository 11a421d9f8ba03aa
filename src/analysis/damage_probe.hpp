// The failure indices of a depth path's points (docs/theory/failure.md 6, items 2-3): at each
// monitored node near the indenter, the shell's strains R and their in-plane derivatives from a
// patch fit of the nodal strains (model/patch_fit.hpp, degree 3 over the nodes within
// DamageSpec::patch_radius and at least the 25 nearest, in the tangent plane), the contact
// pressure on the loaded face (Hertzian or nodal, DamageSpec::face_pressure), the 3-D ply stresses
// recovered through the thickness (section/through_thickness_recovery.hpp, first-order or refined),
// and the criteria of the case at the bottom, middle and top of every ply and at every interface
// (damage/through_thickness_failure.hpp). The state's `failure` gets, per criterion, the largest
// index over the monitored nodes and where it is.
//
// Every step is linear in the displacements and pressures except the indices, which are
// homogeneous of degree 1 in the stress (damage/failure_index.hpp): with linear kinematics and
// a fixed contact set the monitored index is exactly proportional to the depth.
//
// The recovery is the flat-plate one; on the paper's cap (h/R ~ 0.05) its curvature terms are
// ~2.5 % (docs/theory/failure.md 6 item 8). In a quarter model the patches of nodes on the
// symmetry planes are one-sided (the fit extrapolates there).
#pragma once

#include <string>
#include <vector>

#include "analysis/damage_spec.hpp"
#include "contact/local_contact_law.hpp"
#include "damage/through_thickness_failure.hpp"
#include "indentation/state_probe.hpp"
#include "model/assembler.hpp"
#include "model/shell_model.hpp"
#include "section/vam_section.hpp"

namespace si {

// What one node gives: its recovered points (bottom, middle, top of every ply, bottom ply
// first) and, per criterion of the case, the indices there.
struct NodeDamage {
  int node = -1;
  std::vector<RecoveredPoint> recovered;
  std::vector<CriterionFailure> failure;  // in DamageSpec::criteria's order
};

class DamageProbe : public StateProbe {
 public:
  // `direction`: the indenter's unit direction of travel (it loads the face its director points
  // away from). `candidates`: the contact candidates, monitored unless spec.radius > 0. Keeps
  // references to model and assembler. Throws an input si::Error naming the material and key
  // when a ply lacks a strength a criterion reads (io/ refuses such a case at reading already).
  // `face_law`: the power law whose Hertz form (k, radius) sizes the resolved face pressure
  // (DamageSpec::face_pressure kHertz); without one (kind kNone) the pressure is the nodal one.
  DamageProbe(const ShellModel& model, const Assembler& assembler, const Laminate& laminate,
              const DamageSpec& spec, const Vector3d& direction, const std::vector<int>& candidates,
              const LocalContactLaw& face_law);

  void measure(const ProbePoint& point, IndentationState& out) const override;

  // The monitored nodes (mesh node indices, ascending) and the reported points: the apex first,
  // then DamageSpec::points, each at its nearest node.
  const std::vector<int>& monitored() const { return monitored_; }
  const std::vector<std::pair<std::string, int>>& reported() const { return reported_; }
  const std::vector<Criterion>& criteria() const { return spec_.criteria; }

  // The recovery and indices at `nodes` (each a monitored node) at a point.
  std::vector<NodeDamage> evaluate(const ProbePoint& point, const std::vector<int>& nodes) const;

 private:
  struct Patch {
    std::vector<int> rows;  // rows of the patch's nodes in the strain table
    // The fit as a linear map of the patch's values: rows value, ,1 ,2, ,11 ,12 ,22, ,111 ,112
    // ,122 ,222 at the node (fit_patch of unit values), so one evaluation is one product.
    Eigen::MatrixXd fit;
  };
  // The averaged nodal strains R of the patch nodes, one row per strain_nodes_ entry.
  Eigen::MatrixXd patch_strains(const std::vector<NodeState>& states) const;
  NodeDamage at_node(int k, const Eigen::MatrixXd& strains, double pressure) const;
  void build_recovery_map();
  std::vector<double> monitored_pressures(const ProbePoint& point) const;
  std::vector<double> hertz_pressures(const ProbePoint& point) const;
  // Distance of mesh node n (reference position) from the indenter's axis through the apex.
  double axial_distance(int n) const;

  const ShellModel& model_;
  const Assembler& assembler_;
  DamageSpec spec_;
  VamSection section_;
  ThroughThicknessFailure failure_;
  LocalContactLaw face_law_;
  Vector3d direction_;
  double loaded_sign_;  // +1: the indenter loads the top face (t+ = -p); -1: the bottom (t- = p)
  std::vector<int> monitored_;
  std::vector<int> monitored_index_;  // per mesh node: position in monitored_, -1 if none
  std::vector<std::pair<std::string, int>> reported_;
  std::vector<Patch> patches_;        // per monitored node
  std::vector<int> strain_nodes_;     // the patches' nodes, each once
  std::vector<int> strain_elements_;  // the elements around them
  // The recovery is linear in R, its derivatives and the face tractions: the stresses of every
  // recovered point (6 rows each, bottom ply first) = recovery_map_ * [R; R,1; R,2; (R,ab;
  // R,abc: refined); t+; t-], built once from unit inputs. The template holds each recovered
  // point's ply and x3 (its strain and warping are not computed: the criteria read the stress).
  Eigen::MatrixXd recovery_map_;
  std::vector<RecoveredPoint> recovered_template_;
};

}  // namespace si
