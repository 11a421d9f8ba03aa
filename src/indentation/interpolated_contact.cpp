#include "indentation/interpolated_contact.hpp"

#include <array>

#include "contact/travel_gap.hpp"
#include "core/error.hpp"
#include "model/dof_map.hpp"
#include "section/gauss_legendre.hpp"
#include "shell/director.hpp"
#include "shell/offset_face.hpp"
#include "shell/shape4.hpp"
#include "shell/strain_matrices.hpp"

namespace si {
namespace {

// A quadrature point's gap beside the indenter's path (see the header).
constexpr double kFarGap = 1e6;  // mm

struct QuadraturePoint {
  double xi, eta, weight;
};

// n x n Gauss-Legendre points, or the four corners with unit weights for n = 0.
std::vector<QuadraturePoint> element_rule(int n) {
  std::vector<QuadraturePoint> rule;
  if (n == 0) {
    for (int a = 0; a < 4; ++a) rule.push_back({kCornerXi[a], kCornerEta[a], 1.0});
    return rule;
  }
  const GaussRule g = gauss_legendre(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      rule.push_back({g.points[i], g.points[j], g.weights[i] * g.weights[j]});
  return rule;
}

}  // namespace

InterpolatedContact integrate_interpolated_contact(const Mesh& mesh, const Assembler& assembler,
                                                   const ShellElement& element,
                                                   const ContactFace& face,
                                                   const std::vector<int>& candidates,
                                                   const InterpolatedContactOptions& options) {
  SI_REQUIRE(assembler.kinematics() == Kinematics::kLinear,
             "the interpolated contact traction needs linear kinematics");
  SI_REQUIRE(options.gauss_points >= 0 && options.gauss_points <= 6,
             "interpolated contact: gauss_points must be 0 (nodal rule) to 6");
  const int nc = static_cast<int>(candidates.size());
  std::vector<int> traction_index(mesh.num_nodes(), -1);
  for (int i = 0; i < nc; ++i) traction_index[candidates[i]] = i;

  InterpolatedContact out;
  out.w = Eigen::VectorXd::Zero(nc);
  out.g0 = Eigen::VectorXd::Zero(nc);
  const std::vector<QuadraturePoint> rule = element_rule(options.gauss_points);
  const std::vector<NodeState> reference = reference_state(mesh);
  const DofMap& dofs = assembler.dofs();
  const double c = face.offset;
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const std::array<int, 4>& nodes = mesh.elements[e];
    std::array<int, 4> row{};
    bool involved = false;
    for (int a = 0; a < 4; ++a) {
      row[a] = traction_index[nodes[a]];
      involved = involved || row[a] >= 0;
    }
    if (!involved) continue;
    out.elements.push_back(e);
    const ElementGeometry& g = assembler.geometry(e);
    std::array<StrainMatrix, 4> B;
    if (options.fbar) B = nodal_strain_matrices(element, g);
    // Rows of C~ for this element in its 20 dofs, one per corner (zero if not a traction node).
    Eigen::Matrix<double, 4, kShellElementDofs> rows =
        Eigen::Matrix<double, 4, kShellElementDofs>::Zero();
    for (const QuadraturePoint& q : rule) {
      const Shape4 L = evaluate_shape4(ShapeSet::kBilinear, q.xi, q.eta);
      const FacePoint f = face_point(g, c, L, q.weight);
      const TravelGap tg = travel_gap(face.indenter, face.direction, f.P, face.first_touch, false);
      // The gap's gradient at this point in the element dofs (node_gap.hpp: [a ; c E^T a] per
      // node, weighted by N_b), plus the F-bar term (a . n)(-R^T Fbar+) with R = sum N_b B_b q.
      Eigen::Matrix<double, 1, kShellElementDofs> gradient =
          Eigen::Matrix<double, 1, kShellElementDofs>::Zero();
      double value = kFarGap;
      if (tg.hits) {
        value = tg.travel - face.first_touch;
        const Vector3d& a = tg.gradient;
        for (int b = 0; b < 4; ++b) {
          const NodeState& r = reference[nodes[b]];
          gradient.segment<3>(kShellNodeDofs * b) = L.N[b] * a.transpose();
          gradient(kShellNodeDofs * b + 3) = L.N[b] * c * a.dot(-r.v2);
          gradient(kShellNodeDofs * b + 4) = L.N[b] * c * a.dot(r.v1);
        }
        if (options.fbar) {
          StrainMatrix Bq = StrainMatrix::Zero();
          for (int b = 0; b < 4; ++b) Bq += L.N[b] * B[b];
          gradient -= a.dot(f.normal) * (options.fbar_top.transpose() * Bq);
        }
      }
      for (int b = 0; b < 4; ++b) {
        if (row[b] < 0) continue;
        const double NdA = L.N[b] * f.area;
        out.w[row[b]] += NdA;
        out.g0[row[b]] += NdA * value;
        rows.row(b) += NdA * gradient;
      }
    }
    const ElementDofs element_dofs = DofMap::element_dofs(nodes);
    for (int b = 0; b < 4; ++b) {
      if (row[b] < 0) continue;
      for (int k = 0; k < kShellElementDofs; ++k) {
        const int eq = dofs.equation(element_dofs[k]);
        if (eq >= 0 && rows(b, k) != 0.0) triplets.emplace_back(row[b], eq, rows(b, k));
      }
    }
  }
  out.C.resize(nc, dofs.num_free());
  out.C.setFromTriplets(triplets.begin(), triplets.end());
  out.C.makeCompressed();
  return out;
}

}  // namespace si
