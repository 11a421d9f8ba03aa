// One-dimensional finite-element model of the normal line of a flat laminated plate, used by the
// variational-asymptotic (VAM) section analysis (Yu, Hodges & Volovoi, IJSS 39 (2002) 5185 and
// Comput. Struct. 81 (2003) 439; reconstruction in shared/docs/vam.md section 4).
//
// Each ply gets `elements_per_ply` C0 Lagrange elements of `order` p (p+1 equally spaced
// nodes); nodes at ply interfaces are shared. DOFs are node-major, 3 per node:
//   V = [w1(node 0), w2(node 0), w3(node 0), w1(node 1), ...],
// with nodes numbered from the bottom face upwards. x3 is measured from the mid-surface
// (the section analysis always works about the mid-surface, vam.md 6.5).
//
// Strain and stress vectors use the Yu ordering [11, 12, 22, 13, 23, 33] with engineering
// shear strains; the 2-D strains are eps = [e11, 2e12, e22, k11, k12+k21, k22] (vam.md 1).
#pragma once

#include <array>
#include <vector>

#include "core/linalg.hpp"
#include "section/laminate.hpp"

namespace si {

struct NormalLineElement {
  int ply = 0;         // index into the laminate's plies (bottom = 0)
  int first_node = 0;  // the element's nodes are first_node .. first_node + order
  double bottom = 0;   // x3 of the element ends, mm
  double top = 0;
};

// Shape functions of one element evaluated at a point x3 (vam.md 4.1).
struct NormalLinePoint {
  int ply = 0;
  int element = 0;
  int first_dof = 0;  // the element's DOFs are the contiguous block first_dof .. +3(p+1)-1
  double x3 = 0;
  Eigen::VectorXd N;   // N_j(x3), j = 0..p
  Eigen::VectorXd dN;  // dN_j/dx3
};

class NormalLineMesh {
 public:
  // Throws an input si::Error for an invalid laminate, order < 1 or elements_per_ply < 1.
  NormalLineMesh(const Laminate& laminate, int order, int elements_per_ply);

  int order() const { return order_; }
  int dofs() const { return 3 * static_cast<int>(nodes_.size()); }
  double thickness() const { return nodes_.back() - nodes_.front(); }
  const std::vector<double>& nodes() const { return nodes_; }
  const std::vector<NormalLineElement>& elements() const { return elements_; }
  // Ply interfaces z_0 = -h/2 < ... < z_N = h/2 (as Laminate::interfaces()).
  const std::vector<double>& interfaces() const { return interfaces_; }
  // Ply stiffness in plate axes, Yu order, MPa.
  const Matrix6d& ply_stiffness(int ply) const { return stiffness_[ply]; }
  int plies() const { return static_cast<int>(stiffness_.size()); }

  // Shape functions at x3 inside ply `ply` (x3 within that ply's bounds, up to round-off);
  // at an interface this picks the side that belongs to `ply`. Throws an input error otherwise.
  NormalLinePoint point(double x3, int ply) const;
  // Shape functions at the reference coordinate xi in [-1, 1] of element `element`.
  NormalLinePoint element_point(int element, double xi) const;

  // Unnormalised kernel K~ (dofs x 3): K~[3j+i, i] = 1, the rigid translations (vam.md 4.2).
  Eigen::MatrixXd kernel() const;

 private:
  int order_;
  std::vector<double> interfaces_;
  std::vector<double> nodes_;
  std::vector<NormalLineElement> elements_;
  std::vector<Matrix6d> stiffness_;
};

// Element operators of vam.md 4.1 (6 x 3(p+1), Yu rows) and the interpolation S (3 x 3(p+1)):
//   gamma_h     : [0, 0, 0, w1', w2', w3']            (x3-derivatives of the warping)
//   gamma_l(a)  : coefficients of w_{,a} in Gamma      (a = 0 for x1, 1 for x2)
//   gamma_eps   : the classical strain field [I, x3 I; 0, 0] of vam.md 2.1
Eigen::MatrixXd gamma_h(const NormalLinePoint& point);
Eigen::MatrixXd gamma_l(const NormalLinePoint& point, int alpha);
Matrix6d gamma_eps(double x3);
Eigen::MatrixXd shape_matrix(const NormalLinePoint& point);

// The assembled matrices of vam.md 4.2. Indices alpha, beta are 0 (x1) and 1 (x2).
struct NormalLineMatrices {
  Eigen::MatrixXd E;                                   // int B_h^T C B_h          (n x n)
  Eigen::MatrixXd D_he;                                // int B_h^T C Gamma_eps    (n x 6)
  Matrix6d D_ee;                                       // int Gamma_eps^T C Gamma_eps
  std::array<Eigen::MatrixXd, 2> D_h;                  // int B_h^T C B_l(alpha)   (n x n)
  std::array<Eigen::MatrixXd, 2> D_le;                 // int B_l(alpha)^T C Gamma_eps (n x 6)
  std::array<std::array<Eigen::MatrixXd, 2>, 2> D_ll;  // int B_l(alpha)^T C B_l(beta)
  Eigen::MatrixXd H_psi;  // (n x 3) H psi, with psi = K~/sqrt(h): the constraint <w> = 0 is
                          // H_psi^T V = 0 and psi^T H psi = I
};

// Gauss-Legendre quadrature with order + 2 points per element (exact for every integrand;
// vam.md 4.1).
NormalLineMatrices assemble_normal_line(const NormalLineMesh& mesh);

}  // namespace si
