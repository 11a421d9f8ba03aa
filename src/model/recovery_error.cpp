#include "model/recovery_error.hpp"

#include <cmath>

#include "model/nodal_resultants.hpp"
#include "shell/shape4.hpp"

namespace si {
namespace {

using Strain8 = Eigen::Matrix<double, 8, 1>;

Strain8 stacked(const ElementStrains& s, int a) {
  Strain8 v;
  v << s.R[a], s.gamma[a];
  return v;
}

double energy_density(const Strain8& e, const ShellLaw& law) {
  const Vector6d r = e.head<6>();
  const Vector2d g = e.tail<2>();
  return r.dot(law.A_R * r) + g.dot(law.G * g);
}

}  // namespace

double RecoveryError::relative() const {
  const double total = solution_norm2 + error_norm2;
  return total > 0 ? std::sqrt(error_norm2 / total) : 0.0;
}

RecoveryError recovery_error(const Mesh& mesh, const Assembler& assembler,
                             const ShellElement& element, const ShellLaw& law,
                             const std::vector<NodeState>& state) {
  const std::vector<ElementStrains> strains = element_strains(mesh, assembler, element, state);
  const Eigen::MatrixXd recovered = average_at_nodes(mesh, strains);
  // The element's 2x2 Gauss points (weights 1), where e_h is the Gauss value itself.
  const double g = 1 / std::sqrt(3.0);
  RecoveryError out;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const ElementGeometry& geo = assembler.geometry(e);
    for (int q = 0; q < 4; ++q) {
      const Shape4 shape =
          evaluate_shape4(ShapeSet::kBilinear, g * kCornerXi[q], g * kCornerEta[q]);
      Vector3d x_xi = Vector3d::Zero(), x_eta = Vector3d::Zero();
      Strain8 difference = Strain8::Zero(), own = Strain8::Zero();
      for (int a = 0; a < 4; ++a) {
        x_xi += shape.N_xi[a] * geo.X[a];
        x_eta += shape.N_eta[a] * geo.X[a];
        const Strain8 e_h = stacked(strains[e], a);
        own += shape.N[a] * e_h;
        difference += shape.N[a] * (recovered.row(mesh.elements[e][a]).transpose() - e_h);
      }
      const double J = x_xi.cross(x_eta).norm();
      out.error_norm2 += J * energy_density(difference, law);
      out.solution_norm2 += J * energy_density(own, law);
    }
  }
  return out;
}

}  // namespace si
