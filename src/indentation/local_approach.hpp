// The local (through-thickness) approach of the indenter towards the shell's contact face, as
// the contact rows see it (contact/local_contact_law.hpp, docs/theory/local-indentation.md):
// candidate i's gap is taken at its face depth h - u_i(alpha), the face dented by a power law's
// Hertz profile (power_law_approach.hpp), and gains the face's approach under the multipliers:
// c_i lambda_i of a thin layer (thin_layer.hpp), or sum_j C_ij lambda_j of the elastic face
// (elastic_face.hpp). Without a local law (the default here) neither.
#pragma once

#include <vector>

#include "contact/hertz_dent.hpp"
#include "continuation/problem.hpp"
#include "core/error.hpp"

namespace si {

class LocalApproach {
 public:
  virtual ~LocalApproach() = default;
  // The dent of the face at mesh node `node` and its rate d/dalpha.
  virtual DentValue dent(int, const cont::Vector&) const { return {}; }
  // Called before a sweep over the candidates with the same multipliers (the rows' residual,
  // signature, Jacobian and outputs): a non-local law computes its approaches once here.
  virtual void prepare(const std::vector<int>& /*nodes*/,
                       const Eigen::Ref<const cont::Vector>& /*lambda*/) const {}
  // The approach at candidate i (mesh node nodes[i]) carried by the candidates' multipliers
  // `lambda` (N), mm.
  virtual double layer(const std::vector<int>& /*nodes*/, int /*i*/,
                       const Eigen::Ref<const cont::Vector>& /*lambda*/) const {
    return 0.0;
  }
  // d layer_i / d lambda_i at mesh node `node`, mm/N: the Newton rows' diagonal share.
  virtual double layer_rate(int /*node*/) const { return 0.0; }
  // Column j of d layer / d lambda over the candidates `nodes` added to `column`, mm/N (the
  // linear fast path's share of the Schur complement).
  virtual void add_compliance_column(const std::vector<int>& nodes, int j,
                                     Eigen::VectorXd& column) const {
    column[j] += layer_rate(nodes[j]);
  }
  // A non-local law's coupling of the candidates' approaches to each other's multipliers: the
  // candidates (indices into `nodes`, ascending) whose approaches each depend on all of their
  // multipliers (a dense block of the Jacobian, row_coupling.hpp; fixed for a candidate set and
  // the law's adapted state), and, for j among them, column j of d layer / d lambda over all the
  // candidates, mm/N (valid after coupling_members() for the same candidates).
  virtual std::vector<int> coupling_members(const std::vector<int>& /*nodes*/) const { return {}; }
  virtual const Eigen::VectorXd& coupling_column(const std::vector<int>& /*nodes*/,
                                                 int /*j*/) const {
    throw Error(ErrorKind::kInternal, "local approach: a coupling column of a law without any");
  }
  // After an accepted point (ContactRows::adapt): a non-local law may widen its coupling as the
  // pressed candidates (lambda > 0) near its edge; true if it did (the pattern is then rebuilt
  // and the point solved again).
  virtual bool adapt(const std::vector<int>& /*nodes*/,
                     const Eigen::Ref<const cont::Vector>& /*lambda*/) {
    return false;
  }
  // What adapt() has changed, for a checkpoint (empty: nothing), and its restoration in a resumed
  // run; false if the values cannot be this law's (another case's checkpoint, an edited one).
  virtual std::vector<double> adapted() const { return {}; }
  virtual bool restore_adapted(const std::vector<double>& values) { return values.empty(); }
  // The position of alpha in z (the dent's column in the contact rows), -1 without one.
  virtual int alpha_index() const { return -1; }
  // A power law's start is regular only at the kink of the NCP function: a gap within
  // roundoff of zero then takes the touch's derivatives (ContactRows::complementarity).
  virtual bool regularizes_touch() const { return false; }
};

}  // namespace si
