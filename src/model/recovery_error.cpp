#include "model/recovery_error.hpp"

#include <cmath>

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
  const int elements = mesh.num_elements();
  std::vector<ElementStrains> strains(static_cast<std::size_t>(elements));
  Eigen::MatrixXd recovered = Eigen::MatrixXd::Zero(8, mesh.num_nodes());
  Eigen::VectorXd count = Eigen::VectorXd::Zero(mesh.num_nodes());
  for (int e = 0; e < elements; ++e) {
    strains[e] = element.strains_at_nodes(assembler.geometry(e), assembler.element_states(state, e),
                                          assembler.kinematics());
    for (int a = 0; a < 4; ++a) {
      recovered.col(mesh.elements[e][a]) += stacked(strains[e], a);
      count[mesh.elements[e][a]] += 1;
    }
  }
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (count[n] > 0) recovered.col(n) /= count[n];

  // 2x2 Gauss points (weights 1) of the bilinear element, nodes counter-clockwise from (-1,-1).
  const double g = 1 / std::sqrt(3.0);
  const double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
  RecoveryError out;
  for (int e = 0; e < elements; ++e) {
    const ElementGeometry& geo = assembler.geometry(e);
    for (int q = 0; q < 4; ++q) {
      const double s = g * xi[q], t = g * eta[q];
      Vector3d x_s = Vector3d::Zero(), x_t = Vector3d::Zero();
      Strain8 difference = Strain8::Zero(), own = Strain8::Zero();
      for (int a = 0; a < 4; ++a) {
        const double N = 0.25 * (1 + xi[a] * s) * (1 + eta[a] * t);
        x_s += 0.25 * xi[a] * (1 + eta[a] * t) * geo.X[a];
        x_t += 0.25 * eta[a] * (1 + xi[a] * s) * geo.X[a];
        const Strain8 e_h = stacked(strains[e], a);
        own += N * e_h;
        difference += N * (recovered.col(mesh.elements[e][a]) - e_h);
      }
      const double J = x_s.cross(x_t).norm();
      out.error_norm2 += J * energy_density(difference, law);
      out.solution_norm2 += J * energy_density(own, law);
    }
  }
  return out;
}

}  // namespace si
