#include "indentation/contact_body.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "contact/travel_gap.hpp"
#include "core/error.hpp"

namespace si {

ContactBody::ContactBody(const Indenter& indenter, const Vector3d& direction, const Mesh& mesh,
                         double face_offset, double reach)
    : indenter_(indenter), direction_(direction), face_offset_(face_offset) {
  const int nn = mesh.num_nodes();
  geometry_.resize(nn);
  points_.resize(nn);
  for (int n = 0; n < nn; ++n) {
    geometry_[n] = {mesh.nodes[n], face_offset};
    points_[n] = mesh.nodes[n] + face_offset * mesh.directors[n];
  }
  double touch = 0;
  try {
    touch = indenter.first_touch(points_);
  } catch (const Error&) {
    throw_input("the " + indenter.name() +
                    " indenter never touches the shell along its direction of travel",
                Where{"", "indenter", indenter.name(), 0});
  }
  if (touch < 0)
    throw_input("the " + indenter.name() + " indenter starts inside the shell (it would have " +
                    "touched it " + std::to_string(-touch) + " mm before its start position)",
                Where{"", "indenter", indenter.name(), 0});

  // Exact touch travels of the reachable nodes; t0 = the smallest.
  std::vector<double> travel;
  for (int n = 0; n < nn; ++n) {
    const TravelGap g = travel_gap(indenter, direction_, points_[n], touch, false);
    if (g.hits && g.travel - touch <= reach) {
      reachable_.push_back(n);
      travel.push_back(g.travel);
    }
  }
  SI_REQUIRE(!reachable_.empty(), "indentation: no node within reach of the indenter");
  const auto first = std::min_element(travel.begin(), travel.end());
  t0_ = *first;
  first_node_ = reachable_[first - travel.begin()];
  // The contact face is the shell's +director side (the outer face, or the mid-surface touched
  // from there). An indenter whose travel does not point into it at the first touch comes from
  // behind: it would pass through the laminate to "touch" the face from inside.
  if (!(direction_.dot(mesh.directors[first_node_]) < 0.0)) {
    const auto text = [](const Vector3d& v) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "[%.3g, %.3g, %.3g]", v.x(), v.y(), v.z());
      return std::string(buf);
    };
    throw_input("the " + indenter.name() +
                    " indenter travels away from the shell's contact face (or along it): at the "
                    "first touch the face's outward normal is " +
                    text(mesh.directors[first_node_]) +
                    "; the direction of travel must point into the face (e.g. [0, 0, -1] from "
                    "above a cap)",
                Where{"", "indenter.direction", text(direction), 0});
  }
  double extent = 0;
  for (const Vector3d& p : points_) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  touch_roundoff_ = 1e-13 * (1 + std::abs(t0_) + extent);
}

}  // namespace si
