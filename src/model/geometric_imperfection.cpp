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

}  // namespace si
