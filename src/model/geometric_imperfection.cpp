#include "model/geometric_imperfection.hpp"

#include <stdexcept>

namespace si {

void add_imperfection(Mesh& mesh, const Eigen::MatrixXd& translations) {
  if (translations.rows() != mesh.num_nodes() || translations.cols() != 3)
    throw std::invalid_argument("add_imperfection: one translation (3 components) per node");
  Mesh before = mesh;
  compute_directors_from_elements(before);
  for (int n = 0; n < mesh.num_nodes(); ++n) mesh.nodes[n] += translations.row(n).transpose();
  Mesh after = mesh;
  compute_directors_from_elements(after);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vector3d turned = mesh.directors[n] + after.directors[n] - before.directors[n];
    // A node whose element normals cancel (no element, a fold) keeps its director.
    if (before.directors[n].squaredNorm() > 0 && after.directors[n].squaredNorm() > 0 &&
        turned.norm() > 0)
      mesh.directors[n] = turned.normalized();
  }
}

void keep_directors_in_symmetry_planes(Mesh& mesh, const std::vector<Support>& supports) {
  for (const Support& s : supports) {
    if (s.kind != SupportKind::kSymmetryPlane || s.plane_axis < 0 || s.plane_axis > 2) continue;
    for (int n : mesh.node_sets.at(s.node_set)) {
      Vector3d& d = mesh.directors[n];
      d[s.plane_axis] = 0.0;
      if (d.norm() > 0) d.normalize();
    }
  }
}

}  // namespace si
