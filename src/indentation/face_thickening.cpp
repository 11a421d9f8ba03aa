#include "indentation/face_thickening.hpp"

#include <map>

#include "core/error.hpp"
#include "shell/offset_face.hpp"
#include "shell/strain_matrices.hpp"

namespace si {

FaceThickening::FaceThickening(const ShellPart& shell, const Vector6d& fbar_top, double offset)
    : shell_(shell), fbar_top_(fbar_top), offset_(offset) {
  SI_REQUIRE(!shell.nonlinear(),
             "the F-bar term of the nodal contact needs linear kinematics (its strains are B q)");
}

DofRow FaceThickening::rise_row(int node) const {
  const ShellModel& model = shell_.model();
  std::map<int, double> sum;
  double weight = 0;
  for (int e : shell_.node_elements(node)) {
    const std::array<int, 4>& nodes = model.mesh.elements[e];
    const ElementGeometry& g = shell_.assembler().geometry(e);
    const std::array<StrainMatrix, 4> B = nodal_strain_matrices(*model.element, g);
    const ElementDofs dofs = DofMap::element_dofs(nodes);
    for (int a = 0; a < 4; ++a) {
      if (nodes[a] != node) continue;
      // the nodal rule's weight: the contact face's area element at the corner
      const double area =
          face_point(g, offset_, evaluate_shape4(ShapeSet::kBilinear, kCornerXi[a], kCornerEta[a]),
                     1.0)
              .area;
      weight += area;
      const Eigen::Matrix<double, 1, kShellElementDofs> rise = -area * fbar_top_.transpose() * B[a];
      for (int k = 0; k < kShellElementDofs; ++k) {
        const int eq = shell_.dofs().equation(dofs[k]);
        if (eq >= 0 && rise(k) != 0.0) sum[eq] += rise(k);
      }
    }
  }
  DofRow row(sum.begin(), sum.end());
  for (auto& entry : row) entry.second /= weight;
  return row;
}

const Vector3d& FaceThickening::director(int node) const {
  return shell_.model().mesh.directors[node];
}

double row_dot(const DofRow& row, const Eigen::Ref<const Eigen::VectorXd>& x) {
  double sum = 0;
  for (const auto& [eq, value] : row) sum += value * x[eq];
  return sum;
}

}  // namespace si
