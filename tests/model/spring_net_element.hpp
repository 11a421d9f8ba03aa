// A FAKE shell element for testing the model layer without the real shell elements: a
// geometrically nonlinear spring net with a director. Its energy, in the nodal positions x_a and
// directors d_a, is
//   W = sum over the 4 edges and 2 diagonals  k/2 (|x_j - x_i| - |X_j - X_i|)^2
//     + sum over the 4 edges                  g/2 ((x_j - x_i) . (d_i + d_j)/2)^2
//     + sum over the 4 nodes                  c/2 |d_a - D_a|^2
// (stretching, a "transverse shear" coupling translations and directors, a director penalty).
// Translations are free rigid-body modes; one clamped edge makes the tangent positive definite.
// The dofs are those of shell/shell_element.hpp: du and rotations a, b about the current v1, v2
// with d(a, b) = exp(skew(a v1 + b v2)) d, so force and tangent are the exact gradient and
// Hessian of W(q) at q = 0 (chain rule below). In linear mode the element returns K0 q, with K0
// the tangent at the reference state and q = (u, the rotation vector from D to d on V1, V2).
#pragma once

#include <array>
#include <cmath>
#include <string>

#include "shell/shell_element.hpp"

namespace si::testing {

// The spring net ignores the section law; this is a zero one to pass to the API.
inline ShellLaw unused_law() {
  return ShellLaw{Matrix6d::Zero(), Matrix2d::Zero()};
}

class SpringNetElement : public ShellElement {
 public:
  SpringNetElement(double k = 1000.0, double g = 500.0, double c = 100.0) : k_(k), g_(g), c_(c) {}
  std::string name() const override { return "spring_net"; }

  void compute(const ElementGeometry& geo, const std::array<NodeState, 4>& nodes, const ShellLaw&,
               Kinematics kinematics, const ElementRequest&, ElementResponse& out) const override {
    if (kinematics == Kinematics::kLinear) {
      std::array<NodeState, 4> ref;
      for (int a = 0; a < 4; ++a) ref[a] = reference_node_state(geo.D[a]);
      ElementResponse k0;
      nonlinear(geo, ref, k0);
      Eigen::Matrix<double, 20, 1> q;
      for (int a = 0; a < 4; ++a) {
        // The rotation vector theta taking D to d, read on the reference axes: the exact inverse
        // of rotate_node(reference_node_state(D), a, b), as shell_element.hpp asks of the linear
        // mode (the static solver sets d that way).
        const Vector3d axis = geo.D[a].cross(nodes[a].d);
        const double s = axis.norm();
        const Vector3d theta =
            s > 1e-12 ? Vector3d(axis * (std::atan2(s, geo.D[a].dot(nodes[a].d)) / s)) : axis;
        q.segment<3>(5 * a) = nodes[a].u;
        q[5 * a + 3] = theta.dot(ref[a].v1);
        q[5 * a + 4] = theta.dot(ref[a].v2);
      }
      out.tangent = k0.tangent;
      out.force = k0.tangent * q;
      out.energy = 0.5 * q.dot(out.force);
      return;
    }
    nonlinear(geo, nodes, out);
  }

  ElementStrains strains_at_nodes(const ElementGeometry&, const std::array<NodeState, 4>&,
                                  Kinematics) const override {
    ElementStrains s;
    for (auto& r : s.R) r.setZero();
    for (auto& g : s.gamma) g.setZero();
    return s;
  }

 private:
  using Vec24 = Eigen::Matrix<double, 24, 1>;
  using Mat24 = Eigen::Matrix<double, 24, 24>;
  static int xi(int a) { return 3 * a; }       // x_a in z = [x0..x3, d0..d3]
  static int di(int a) { return 12 + 3 * a; }  // d_a in z

  void nonlinear(const ElementGeometry& geo, const std::array<NodeState, 4>& nodes,
                 ElementResponse& out) const {
    std::array<Vector3d, 4> x, d;
    for (int a = 0; a < 4; ++a) {
      x[a] = geo.X[a] + nodes[a].u;
      d[a] = nodes[a].d;
    }
    Vec24 G = Vec24::Zero();
    Mat24 H = Mat24::Zero();
    double W = 0;
    const Matrix3d I = Matrix3d::Identity();
    const int pairs[6][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}};
    for (const auto& p : pairs) {  // stretching
      const int i = p[0], j = p[1];
      const Vector3d r = x[j] - x[i];
      const double l = r.norm(), L = (geo.X[j] - geo.X[i]).norm();
      const Vector3d e = r / l;
      W += 0.5 * k_ * (l - L) * (l - L);
      G.segment<3>(xi(j)) += k_ * (l - L) * e;
      G.segment<3>(xi(i)) -= k_ * (l - L) * e;
      const Matrix3d h = k_ * (e * e.transpose() + (l - L) / l * (I - e * e.transpose()));
      H.block<3, 3>(xi(i), xi(i)) += h;
      H.block<3, 3>(xi(j), xi(j)) += h;
      H.block<3, 3>(xi(i), xi(j)) -= h;
      H.block<3, 3>(xi(j), xi(i)) -= h;
    }
    for (int i = 0; i < 4; ++i) {  // shear coupling
      const int j = (i + 1) % 4;
      const Vector3d r = x[j] - x[i], m = 0.5 * (d[i] + d[j]);
      const double s = r.dot(m);
      W += 0.5 * g_ * s * s;
      Vec24 ds = Vec24::Zero();
      ds.segment<3>(xi(j)) = m;
      ds.segment<3>(xi(i)) = -m;
      ds.segment<3>(di(i)) = 0.5 * r;
      ds.segment<3>(di(j)) = 0.5 * r;
      G += g_ * s * ds;
      H += g_ * ds * ds.transpose();
      for (int dn : {i, j}) {  // d2s/dx dd = +-I/2
        H.block<3, 3>(xi(j), di(dn)) += 0.5 * g_ * s * I;
        H.block<3, 3>(di(dn), xi(j)) += 0.5 * g_ * s * I;
        H.block<3, 3>(xi(i), di(dn)) -= 0.5 * g_ * s * I;
        H.block<3, 3>(di(dn), xi(i)) -= 0.5 * g_ * s * I;
      }
    }
    for (int a = 0; a < 4; ++a) {  // director penalty
      const Vector3d dd = d[a] - geo.D[a];
      W += 0.5 * c_ * dd.squaredNorm();
      G.segment<3>(di(a)) += c_ * dd;
      H.block<3, 3>(di(a), di(a)) += c_ * I;
    }
    // Chain rule to q = (du, rotation a about v1, b about v2) per node.
    Eigen::Matrix<double, 24, 20> J = Eigen::Matrix<double, 24, 20>::Zero();
    out.tangent.setZero();
    for (int a = 0; a < 4; ++a) {
      J.block<3, 3>(xi(a), 5 * a) = I;
      const std::array<Vector3d, 2> w = {nodes[a].v1, nodes[a].v2};
      for (int al = 0; al < 2; ++al) {
        J.block<3, 1>(di(a), 5 * a + 3 + al) = w[al].cross(d[a]);
        for (int be = 0; be < 2; ++be) {
          // d2 d / d alpha d beta of exp(skew(w)) d at 0 (symmetric part of w x (w x d)).
          const Vector3d s2 =
              0.5 * (w[al].cross(w[be].cross(d[a])) + w[be].cross(w[al].cross(d[a])));
          out.tangent(5 * a + 3 + al, 5 * a + 3 + be) += G.segment<3>(di(a)).dot(s2);
        }
      }
    }
    out.force = J.transpose() * G;
    out.tangent += J.transpose() * H * J;
    out.energy = W;
  }

  double k_, g_, c_;
};

}  // namespace si::testing
