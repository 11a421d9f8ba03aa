#include "model/shell_chart.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "model/assembler.hpp"

namespace si {
namespace {

// K(i, j), which must be in K's pattern: inserting would silently change the pattern the
// linear solver analysed.
double& existing_entry(SparseMatrix& K, int i, int j) {
  const int* begin = K.innerIndexPtr() + K.outerIndexPtr()[j];
  const int* end = K.innerIndexPtr() + K.outerIndexPtr()[j + 1];
  const int* it = std::lower_bound(begin, end, i);
  SI_REQUIRE(it != end && *it == i, "shell chart: entry not in the Jacobian's pattern");
  return K.valuePtr()[it - K.innerIndexPtr()];
}

}  // namespace

Matrix3d so3_left_jacobian(const Vector3d& theta) {
  const double t = theta.norm();
  Matrix3d S;
  S << 0, -theta.z(), theta.y(), theta.z(), 0, -theta.x(), -theta.y(), theta.x(), 0;
  // (1 - cos t)/t^2 and (t - sin t)/t^3 by their Taylor series near 0 (cancellation).
  const double a = t < 1e-4 ? 0.5 - t * t / 24 : (1 - std::cos(t)) / (t * t);
  const double b = t < 1e-4 ? 1.0 / 6 - t * t / 120 : (t - std::sin(t)) / (t * t * t);
  return Matrix3d::Identity() + a * S + b * S * S;
}

ShellChart::ShellChart(const Mesh& mesh, const DofMap& dofs)
    : mesh_(mesh), dofs_(dofs), reference_(reference_state(mesh)), base_(reference_) {
  SI_REQUIRE(dofs.num_nodes() == mesh.num_nodes(), "shell chart: dof map and mesh differ");
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    NodeRotation r{n, dofs.equation(DofMap::dof(n, 3)), dofs.equation(DofMap::dof(n, 4))};
    if (r.eq_a >= 0 || r.eq_b >= 0) rotations_.push_back(r);
  }
}

Vector3d ShellChart::theta(const Eigen::VectorXd& x, const NodeRotation& r) const {
  const NodeState& ref = base_[r.node];
  const double a = r.eq_a >= 0 ? x[r.eq_a] : 0.0;
  const double b = r.eq_b >= 0 ? x[r.eq_b] : 0.0;
  return a * ref.v1 + b * ref.v2;
}

void ShellChart::states(const Eigen::VectorXd& x, double prescribed_scale,
                        std::vector<NodeState>& out) const {
  SI_REQUIRE(x.size() == size(), "shell chart: coordinate vector of the wrong size");
  out = reference_;
  for (int n = 0; n < mesh_.num_nodes(); ++n)
    for (int l = 0; l < 3; ++l) {
      const int dof = DofMap::dof(n, l);
      const int eq = dofs_.equation(dof);
      out[n].u[l] = eq >= 0 ? x[eq] : prescribed_scale * dofs_.prescribed_value(dof);
    }
  for (const NodeRotation& r : rotations_) {
    const Matrix3d Q = rotation_matrix(theta(x, r));
    const NodeState& base = base_[r.node];
    NodeState& s = out[r.node];
    s.d = Q * base.d;
    s.v1 = Q * base.v1;
    s.v2 = Q * base.v2;
  }
}

int ShellChart::rebase(Eigen::VectorXd& x, double max_angle) {
  SI_REQUIRE(x.size() == size(), "shell chart: coordinate vector of the wrong size");
  int count = 0;
  for (const NodeRotation& r : rotations_) {
    const Vector3d th = theta(x, r);
    if (!(th.norm() > max_angle)) continue;
    const Matrix3d Q = rotation_matrix(th);
    NodeState& base = base_[r.node];
    base.d = Q * base.d;
    base.v1 = Q * base.v1;
    base.v2 = Q * base.v2;
    if (r.eq_a >= 0) x[r.eq_a] = 0.0;
    if (r.eq_b >= 0) x[r.eq_b] = 0.0;
    ++count;
  }
  return count;
}

void ShellChart::set_base(std::vector<NodeState> base) {
  SI_REQUIRE(base.size() == base_.size(), "shell chart: one base frame per node needed");
  base_ = std::move(base);
}

Eigen::VectorXd ShellChart::coordinates(const std::vector<NodeState>& state) const {
  SI_REQUIRE(static_cast<int>(state.size()) == mesh_.num_nodes(),
             "shell chart: one state per node needed");
  Eigen::VectorXd x(size());
  for (int n = 0; n < mesh_.num_nodes(); ++n)
    for (int l = 0; l < 3; ++l) {
      const int eq = dofs_.equation(DofMap::dof(n, l));
      if (eq >= 0) x[eq] = state[n].u[l];
    }
  for (const NodeRotation& r : rotations_) {
    const Vector3d th = turn(r.node, base_[r.node].d, state[r.node].d);
    if (r.eq_a >= 0) x[r.eq_a] = th.dot(base_[r.node].v1);
    if (r.eq_b >= 0) x[r.eq_b] = th.dot(base_[r.node].v2);
  }
  return x;
}

Vector3d ShellChart::rotation_vector(int node, const Vector3d& d) const {
  return turn(node, reference_[node].d, d);
}

Vector3d ShellChart::turn(int node, const Vector3d& D, const Vector3d& d) {
  const Vector3d axis = D.cross(d);
  const double angle = std::atan2(axis.norm(), D.dot(d));
  if (angle > M_PI - 1e-6)
    throw_numerical("node " + std::to_string(node) + " has turned by pi: outside the shell chart");
  return axis.norm() > 0 ? Vector3d(axis.normalized() * angle) : Vector3d::Zero();
}

void ShellChart::node_transform(const Eigen::VectorXd& x, const NodeRotation& rot, Matrix2d& T,
                                Eigen::RowVector2d& drill) const {
  const NodeState& ref = base_[rot.node];
  const Vector3d th = theta(x, rot);
  const Matrix3d Q = rotation_matrix(th);
  const Vector3d d = Q * ref.d, v1 = Q * ref.v1, v2 = Q * ref.v2;
  Eigen::Matrix<double, 3, 2> W;  // spatial angular velocity per unit (da, db)
  W.col(0) = ref.v1;
  W.col(1) = ref.v2;
  W = so3_left_jacobian(th) * W;
  T.row(0) = v1.transpose() * W;
  T.row(1) = v2.transpose() * W;
  drill = d.transpose() * W;
}

std::vector<ShellChart::RotationBlock> ShellChart::to_chart_jacobian(const Eigen::VectorXd& x,
                                                                     const Eigen::VectorXd& r,
                                                                     SparseMatrix& K) const {
  SI_REQUIRE(K.cols() >= size() && K.rows() >= size() && r.size() == size(),
             "shell chart: Jacobian or residual of the wrong size");
  SI_REQUIRE(K.isCompressed(), "shell chart: the Jacobian must be compressed");
  std::vector<RotationBlock> blocks;
  blocks.reserve(rotations_.size());
  for (const NodeRotation& rot : rotations_) {
    Matrix2d T;
    Eigen::RowVector2d drill;
    node_transform(x, rot, T, drill);
    RotationBlock block;
    block.eq_a = rot.eq_a;
    block.eq_b = rot.eq_b;
    block.T = rot.eq_a >= 0 && rot.eq_b >= 0 ? T : Matrix2d(T.diagonal().asDiagonal());
    blocks.push_back(block);

    // Columns: K T. A prescribed component has neither column nor chart coordinate; with the
    // other one free, theta stays on one reference axis and T is diagonal there (T(0,1) = 0).
    if (rot.eq_a >= 0 && rot.eq_b >= 0) {
      const int ca = rot.eq_a, cb = rot.eq_b;
      const int na = K.outerIndexPtr()[ca + 1] - K.outerIndexPtr()[ca];
      const int nb = K.outerIndexPtr()[cb + 1] - K.outerIndexPtr()[cb];
      SI_REQUIRE(na == nb, "shell chart: rotation columns of a node differ in pattern");
      double* va = K.valuePtr() + K.outerIndexPtr()[ca];
      double* vb = K.valuePtr() + K.outerIndexPtr()[cb];
      const int* ia = K.innerIndexPtr() + K.outerIndexPtr()[ca];
      const int* ib = K.innerIndexPtr() + K.outerIndexPtr()[cb];
      for (int k = 0; k < na; ++k) {
        SI_REQUIRE(ia[k] == ib[k], "shell chart: rotation columns of a node differ in pattern");
        const double ka = va[k], kb = vb[k];
        va[k] = ka * T(0, 0) + kb * T(1, 0);
        vb[k] = ka * T(0, 1) + kb * T(1, 1);
      }
      // Drilling: the current axes turn by omega.d about d (see the header).
      const double ra = r[ca], rb = r[cb];
      existing_entry(K, ca, ca) += rb * drill[0];
      existing_entry(K, ca, cb) += rb * drill[1];
      existing_entry(K, cb, ca) -= ra * drill[0];
      existing_entry(K, cb, cb) -= ra * drill[1];
    } else {
      const int c = rot.eq_a >= 0 ? rot.eq_a : rot.eq_b;
      const int i = rot.eq_a >= 0 ? 0 : 1;
      for (SparseMatrix::InnerIterator it(K, c); it; ++it) it.valueRef() *= T(i, i);
    }
  }
  return blocks;
}

SparseMatrix ShellChart::transform(int n, const std::vector<RotationBlock>& blocks) {
  std::vector<bool> rotation(static_cast<std::size_t>(n), false);
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(static_cast<std::size_t>(n) + 2 * blocks.size());
  for (const RotationBlock& b : blocks) {
    const int eq[2] = {b.eq_a, b.eq_b};
    for (int r = 0; r < 2; ++r) {
      if (eq[r] < 0) continue;
      rotation[static_cast<std::size_t>(eq[r])] = true;
      for (int c = 0; c < 2; ++c)
        if (eq[c] >= 0) t.emplace_back(eq[r], eq[c], b.T(r, c));
    }
  }
  for (int i = 0; i < n; ++i)
    if (!rotation[static_cast<std::size_t>(i)]) t.emplace_back(i, i, 1.0);
  SparseMatrix T(n, n);
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

}  // namespace si
