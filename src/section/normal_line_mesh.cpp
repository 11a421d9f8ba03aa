#include "section/normal_line_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

// Lagrange basis on p+1 equally spaced nodes of [-1, 1] and its xi-derivative.
void lagrange_basis(int p, double xi, Eigen::VectorXd& N, Eigen::VectorXd& dN) {
  N.resize(p + 1);
  dN.resize(p + 1);
  auto node = [p](int j) { return -1.0 + 2.0 * j / p; };
  for (int j = 0; j <= p; ++j) {
    double value = 1.0, slope = 0.0;
    for (int m = 0; m <= p; ++m) {
      if (m == j) continue;
      const double factor = (xi - node(m)) / (node(j) - node(m));
      slope = slope * factor + value / (node(j) - node(m));  // product rule, accumulated
      value *= factor;
    }
    N(j) = value;
    dN(j) = slope;
  }
}

}  // namespace

NormalLineMesh::NormalLineMesh(const Laminate& laminate, int order, int elements_per_ply)
    : order_(order) {
  laminate.validate();
  if (order < 1)
    throw_input("the normal-line element order must be at least 1",
                Where{"", "order", std::to_string(order), 0});
  if (elements_per_ply < 1)
    throw_input("the number of normal-line elements per ply must be at least 1",
                Where{"", "elements_per_ply", std::to_string(elements_per_ply), 0});
  interfaces_ = laminate.interfaces();
  const std::vector<double>& z = interfaces_;
  nodes_.push_back(z.front());
  for (size_t k = 0; k < laminate.plies.size(); ++k) {
    stiffness_.push_back(laminate.plies[k].stiffness_yu());
    const double step = (z[k + 1] - z[k]) / elements_per_ply;
    for (int e = 0; e < elements_per_ply; ++e) {
      const double a = z[k] + e * step;
      const double b = (e + 1 == elements_per_ply) ? z[k + 1] : a + step;
      elements_.push_back(
          NormalLineElement{static_cast<int>(k), static_cast<int>(nodes_.size()) - 1, a, b});
      for (int j = 1; j <= order; ++j) nodes_.push_back(a + (b - a) * j / order);
      nodes_.back() = b;
    }
  }
}

NormalLinePoint NormalLineMesh::element_point(int element, double xi) const {
  const NormalLineElement& el = elements_[element];
  const double jacobian = 0.5 * (el.top - el.bottom);
  NormalLinePoint pt;
  pt.ply = el.ply;
  pt.element = element;
  pt.first_dof = 3 * el.first_node;
  pt.x3 = 0.5 * (el.top + el.bottom) + jacobian * xi;
  lagrange_basis(order_, xi, pt.N, pt.dN);
  pt.dN /= jacobian;
  return pt;
}

NormalLinePoint NormalLineMesh::point(double x3, int ply) const {
  if (ply < 0 || ply >= plies()) {
    throw_input("ply index " + std::to_string(ply) + " is out of range (the laminate has " +
                std::to_string(plies()) + " plies)");
  }
  const double tol = 1e-12 * thickness();
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NormalLineElement& el = elements_[e];
    if (el.ply != ply) continue;
    const bool last_of_ply = (e + 1 == elements_.size()) || elements_[e + 1].ply != ply;
    const bool first_of_ply = (e == 0) || elements_[e - 1].ply != ply;
    const bool above_bottom = x3 >= el.bottom - (first_of_ply ? tol : 0.0);
    const bool below_top = last_of_ply ? x3 <= el.top + tol : x3 < el.top;
    if (above_bottom && below_top) {
      const double xi = (2.0 * x3 - el.top - el.bottom) / (el.top - el.bottom);
      NormalLinePoint pt = element_point(static_cast<int>(e), std::clamp(xi, -1.0, 1.0));
      pt.x3 = x3;
      return pt;
    }
  }
  std::ostringstream os;
  os << "x3 = " << x3 << " mm is not inside ply " << ply + 1 << " (x3 is measured from the "
     << "mid-surface)";
  throw_input(os.str());
}

Eigen::MatrixXd NormalLineMesh::kernel() const {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs(), 3);
  for (int j = 0; j < dofs() / 3; ++j) K.block<3, 3>(3 * j, 0).setIdentity();
  return K;
}

Eigen::MatrixXd gamma_h(const NormalLinePoint& point) {
  const int nodes = static_cast<int>(point.N.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 3 * nodes);
  for (int j = 0; j < nodes; ++j)
    for (int i = 0; i < 3; ++i) B(3 + i, 3 * j + i) = point.dN(j);  // 2G13, 2G23, G33
  return B;
}

Eigen::MatrixXd gamma_l(const NormalLinePoint& point, int alpha) {
  // Rows receiving w1,a  w2,a  w3,a (vam.md 2.1): a = 1 -> (11, 12, 13); a = 2 -> (12, 22, 23).
  static constexpr int kRows[2][3] = {{0, 1, 3}, {1, 2, 4}};
  const int nodes = static_cast<int>(point.N.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 3 * nodes);
  for (int j = 0; j < nodes; ++j)
    for (int i = 0; i < 3; ++i) B(kRows[alpha][i], 3 * j + i) = point.N(j);
  return B;
}

Matrix6d gamma_eps(double x3) {
  Matrix6d G = Matrix6d::Zero();
  for (int i = 0; i < 3; ++i) {
    G(i, i) = 1.0;
    G(i, 3 + i) = x3;
  }
  return G;
}

Eigen::MatrixXd shape_matrix(const NormalLinePoint& point) {
  const int nodes = static_cast<int>(point.N.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(3, 3 * nodes);
  for (int j = 0; j < nodes; ++j)
    for (int i = 0; i < 3; ++i) S(i, 3 * j + i) = point.N(j);
  return S;
}

NormalLineMatrices assemble_normal_line(const NormalLineMesh& mesh) {
  const int n = mesh.dofs();
  const int m = 3 * (mesh.order() + 1);
  NormalLineMatrices out;
  out.E = Eigen::MatrixXd::Zero(n, n);
  out.D_he = Eigen::MatrixXd::Zero(n, 6);
  out.D_ee = Matrix6d::Zero();
  out.H_psi = Eigen::MatrixXd::Zero(n, 3);
  for (int a = 0; a < 2; ++a) {
    out.D_h[a] = Eigen::MatrixXd::Zero(n, n);
    out.D_le[a] = Eigen::MatrixXd::Zero(n, 6);
    for (int b = 0; b < 2; ++b) out.D_ll[a][b] = Eigen::MatrixXd::Zero(n, n);
  }
  const GaussRule rule = gauss_legendre(mesh.order() + 2);
  const double inv_sqrt_h = 1.0 / std::sqrt(mesh.thickness());
  for (size_t e = 0; e < mesh.elements().size(); ++e) {
    const NormalLineElement& el = mesh.elements()[e];
    const Matrix6d& C = mesh.ply_stiffness(el.ply);
    const double jacobian = 0.5 * (el.top - el.bottom);
    for (size_t g = 0; g < rule.points.size(); ++g) {
      const NormalLinePoint pt = mesh.element_point(static_cast<int>(e), rule.points[g]);
      const double w = rule.weights[g] * jacobian;
      const int d = pt.first_dof;
      const Eigen::MatrixXd Bh = gamma_h(pt);
      const Eigen::MatrixXd CBh = C * Bh;
      const Matrix6d Ge = gamma_eps(pt.x3);
      const Matrix6d CGe = C * Ge;
      const std::array<Eigen::MatrixXd, 2> Bl{gamma_l(pt, 0), gamma_l(pt, 1)};
      out.E.block(d, d, m, m) += w * Bh.transpose() * CBh;
      out.D_he.middleRows(d, m) += w * Bh.transpose() * CGe;
      out.D_ee += w * Ge.transpose() * CGe;
      for (int a = 0; a < 2; ++a) {
        out.D_h[a].block(d, d, m, m) += w * CBh.transpose() * Bl[a];
        out.D_le[a].middleRows(d, m) += w * Bl[a].transpose() * CGe;
        for (int b = 0; b < 2; ++b)
          out.D_ll[a][b].block(d, d, m, m) += w * Bl[a].transpose() * C * Bl[b];
      }
      for (int j = 0; j <= mesh.order(); ++j)
        for (int i = 0; i < 3; ++i) out.H_psi(d + 3 * j + i, i) += w * pt.N(j) * inv_sqrt_h;
    }
  }
  return out;
}

}  // namespace si
