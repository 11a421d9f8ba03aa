#include "indentation/power_law_approach.hpp"

#include <algorithm>
#include <cmath>

namespace si {

// r_n of the dent profile: the distance of node n's reference contact point from the indenter's
// axis, measured from the first-touch node's distance r_f as (r_n^2 - r_f^2)^0.5 (0 inside it).
// With a node on the axis (the apex under the default pose) r_f = 0 up to roundoff, which this
// removes; without one (an indenter off the nodes' lines) the first-touch node still counts as
// the patch's centre. Either way the row closed at first touch has d g / d alpha = 1 at
// alpha = 0, which keeps the start's Jacobian regular (local-indentation.md 3). For a sphere
// over a flat face r_n^2 - r_f^2 = 2 R (s(P_n) - t0) to O(r^4/R^2): the shifted radius is the
// one the rigid sphere's own gap profile sees. Reference configuration: Hertz's profile is a
// small-strain field over the undeformed surface, and the face's lateral motion is of the order
// of the half-space's own radial surface displacement, which Hertz's theory neglects.
PowerLawApproach::PowerLawApproach(const LocalContactLaw& law, const ContactBody& body,
                                   const ContactRows& rows, double symmetry_factor)
    : law_(law), rows_(rows), symmetry_factor_(symmetry_factor) {
  const Vector3d q = body.indenter().pose().position;
  const Vector3d& e = body.direction();
  const auto axis_distance = [&](const Vector3d& p) {
    const Vector3d d = p - q;
    return (d - d.dot(e) * e).norm();
  };
  const std::vector<Vector3d>& points = body.face_points();
  const double rf = axis_distance(points[body.first_node()]);
  dent_radius_.resize(points.size());
  for (std::size_t n = 0; n < points.size(); ++n) {
    const double r = axis_distance(points[n]);
    dent_radius_[n] = std::sqrt(std::max(r * r - rf * rf, 0.0));
  }
  dent_radius_[body.first_node()] = 0;
}

DentValue PowerLawApproach::dent(int node, const cont::Vector& z) const {
  const double alpha = z[first()];
  if (!dent_profile_ || dent_profile_->alpha != alpha) dent_profile_ = law_.dent_profile(alpha);
  return dent_profile_->at(dent_radius_[node]);
}

void PowerLawApproach::add_pattern(Triplets& t) const {
  const int a = first();
  for (int i = 0; i < rows_.size(); ++i) t.emplace_back(a, rows_.first() + i, 0.0);
  t.emplace_back(a, a, 0.0);
}

void PowerLawApproach::locate(const SparseMatrix& J) {
  const int a = first();
  row_slots_.resize(rows_.size());
  for (int i = 0; i < rows_.size(); ++i) row_slots_[i] = value_slot(J, a, rows_.first() + i);
  diagonal_ = value_slot(J, a, a);
}

void PowerLawApproach::residual(const TermPoint& p, cont::Vector& F) {
  const double alpha = p.z[first()];
  F[first()] = symmetry_factor_ * rows_.multipliers(p.z).sum() - law_.force(alpha);
}

// alpha's row sums the multipliers; the rows' own alpha column is theirs (contact_rows.cpp).
void PowerLawApproach::add_jacobian(const TermPoint& p, double* J,
                                    std::vector<ContactJacobianRow>*) {
  for (int slot : row_slots_) J[slot] += symmetry_factor_;
  J[diagonal_] -= law_.stiffness(p.z[first()]);
}

void PowerLawApproach::outputs(const TermPoint& p, IndentationState& out) const {
  out.local_indentation = p.z[first()];
  out.local_energy = law_.energy(p.z[first()]);
}

}  // namespace si
