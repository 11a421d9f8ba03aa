#include "model/loads.hpp"

#include <cmath>

#include "core/error.hpp"
#include "model/dof_map.hpp"
#include "model/node_set.hpp"

namespace si {
namespace {

// Bilinear shape functions on [-1,1]^2, nodes at (-1,-1), (1,-1), (1,1), (-1,1).
constexpr double kXi[4] = {-1, 1, 1, -1};
constexpr double kEta[4] = {-1, -1, 1, 1};

struct ShapeAt {
  std::array<double, 4> N, dxi, deta;
};

ShapeAt shape_at(double xi, double eta) {
  ShapeAt s;
  for (int a = 0; a < 4; ++a) {
    s.N[a] = 0.25 * (1 + kXi[a] * xi) * (1 + kEta[a] * eta);
    s.dxi[a] = 0.25 * kXi[a] * (1 + kEta[a] * eta);
    s.deta[a] = 0.25 * kEta[a] * (1 + kXi[a] * xi);
  }
  return s;
}

const std::array<ShapeAt, 4>& gauss_shapes() {
  static const std::array<ShapeAt, 4> shapes = [] {
    const double g = 1.0 / std::sqrt(3.0);  // 2x2 Gauss, unit weights
    return std::array<ShapeAt, 4>{shape_at(-g, -g), shape_at(g, -g), shape_at(g, g),
                                  shape_at(-g, g)};
  }();
  return shapes;
}

Matrix3d skew(const Vector3d& v) {
  Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

std::array<Vector3d, 4> reference_positions(const Mesh& mesh, int element) {
  std::array<Vector3d, 4> x;
  for (int a = 0; a < 4; ++a) x[a] = mesh.nodes[mesh.elements[element][a]];
  return x;
}

void add_translation(Eigen::VectorXd& f, int node, const Vector3d& force) {
  f.segment<3>(DofMap::dof(node, 0)) += force;
}

template <class Positions>
void add_pressure(const Mesh& mesh, const PressureLoad& pl, Positions&& positions,
                  Eigen::VectorXd& f) {
  const auto one = [&](int e) {
    const Eigen::Matrix<double, 12, 1> fe = pressure_nodal_forces(positions(e), pl.pressure);
    for (int a = 0; a < 4; ++a) add_translation(f, mesh.elements[e][a], fe.segment<3>(3 * a));
  };
  if (pl.elements.empty()) {
    for (int e = 0; e < mesh.num_elements(); ++e) one(e);
  } else {
    for (int e : pl.elements) one(e);
  }
}

bool finite(const Vector3d& v) {
  return v.allFinite();
}

}  // namespace

bool Loads::has_follower() const {
  for (const PressureLoad& p : pressures)
    if (p.follower) return true;
  return false;
}

bool is_drilling(const Vector3d& moment, const Vector3d& director) {
  return std::abs(moment.dot(director)) > 1e-12 * moment.norm();
}

void validate(const Mesh& mesh, const Loads& loads) {
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const std::string who = "point load " + std::to_string(i);
    const std::vector<int>& nodes = find_node_set(mesh, loads.points[i].node_set, who);
    if (nodes.empty()) throw_input(who + ": node set '" + loads.points[i].node_set + "' is empty");
    if (!finite(loads.points[i].force)) throw_input(who + ": force is not finite");
  }
  for (std::size_t i = 0; i < loads.lines.size(); ++i) {
    const std::string who = "line load " + std::to_string(i);
    const LineLoad& l = loads.lines[i];
    if (l.edge_nodes.size() < 2) throw_input(who + ": an edge needs at least 2 ordered nodes");
    for (int n : l.edge_nodes)
      if (n < 0 || n >= mesh.num_nodes())
        throw_input(who + ": node " + std::to_string(n) + " is not in the mesh");
    for (std::size_t s = 0; s + 1 < l.edge_nodes.size(); ++s)
      if ((mesh.nodes[l.edge_nodes[s + 1]] - mesh.nodes[l.edge_nodes[s]]).norm() == 0.0)
        throw_input(who + ": nodes " + std::to_string(l.edge_nodes[s]) + " and " +
                    std::to_string(l.edge_nodes[s + 1]) + " coincide (zero-length segment)");
    if (!finite(l.force_per_length)) throw_input(who + ": force per length is not finite");
  }
  for (std::size_t i = 0; i < loads.moments.size(); ++i) {
    const std::string who = "nodal moment " + std::to_string(i);
    const NodalMoment& m = loads.moments[i];
    const std::vector<int>& nodes = find_node_set(mesh, m.node_set, who);
    if (nodes.empty()) throw_input(who + ": node set '" + m.node_set + "' is empty");
    if (!finite(m.moment)) throw_input(who + ": moment is not finite");
    for (int n : nodes)
      if (is_drilling(m.moment, mesh.directors[n]))
        throw_input(who + ": the moment has a component along the director of node " +
                    std::to_string(n) + " (drilling), which the 5-dof nodes cannot carry");
  }
  for (std::size_t i = 0; i < loads.pressures.size(); ++i) {
    const std::string who = "pressure load " + std::to_string(i);
    if (!std::isfinite(loads.pressures[i].pressure)) throw_input(who + ": pressure is not finite");
    for (int e : loads.pressures[i].elements)
      if (e < 0 || e >= mesh.num_elements())
        throw_input(who + ": element " + std::to_string(e) + " is not in the mesh (" +
                    std::to_string(mesh.num_elements()) + " elements)");
  }
}

Eigen::VectorXd fixed_load_vector(const Mesh& mesh, const Loads& loads) {
  validate(mesh, loads);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(kShellNodeDofs * mesh.num_nodes());
  for (const PointLoad& p : loads.points) {
    const std::vector<int>& nodes = mesh.node_sets.at(p.node_set);
    const Vector3d each = p.per_node ? p.force : Vector3d(p.force / double(nodes.size()));
    for (int n : nodes) add_translation(f, n, each);
  }
  for (const LineLoad& l : loads.lines) {
    for (std::size_t s = 0; s + 1 < l.edge_nodes.size(); ++s) {
      const int a = l.edge_nodes[s], b = l.edge_nodes[s + 1];
      const Vector3d half = 0.5 * (mesh.nodes[b] - mesh.nodes[a]).norm() * l.force_per_length;
      add_translation(f, a, half);
      add_translation(f, b, half);
    }
  }
  for (const NodalMoment& m : loads.moments) {
    const std::vector<int>& nodes = mesh.node_sets.at(m.node_set);
    const Vector3d each = m.per_node ? m.moment : Vector3d(m.moment / double(nodes.size()));
    for (int n : nodes) {
      const NodeState axes = reference_node_state(mesh.directors[n]);
      f[DofMap::dof(n, 3)] += each.dot(axes.v1);
      f[DofMap::dof(n, 4)] += each.dot(axes.v2);
    }
  }
  for (const PressureLoad& pl : loads.pressures)
    if (!pl.follower)
      add_pressure(
          mesh, pl, [&](int e) { return reference_positions(mesh, e); }, f);
  return f;
}

std::array<Vector3d, 4> current_positions(const Mesh& mesh, const std::vector<NodeState>& state,
                                          int element) {
  std::array<Vector3d, 4> x;
  for (int a = 0; a < 4; ++a) {
    const int n = mesh.elements[element][a];
    x[a] = mesh.nodes[n] + state[n].u;
  }
  return x;
}

Eigen::VectorXd follower_load_vector(const Mesh& mesh, const Loads& loads,
                                     const std::vector<NodeState>& state) {
  SI_ASSERT(static_cast<int>(state.size()) == mesh.num_nodes());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(kShellNodeDofs * mesh.num_nodes());
  for (const PressureLoad& pl : loads.pressures)
    if (pl.follower)
      add_pressure(
          mesh, pl, [&](int e) { return current_positions(mesh, state, e); }, f);
  return f;
}

Eigen::Matrix<double, 12, 1> pressure_nodal_forces(const std::array<Vector3d, 4>& x, double p) {
  Eigen::Matrix<double, 12, 1> f = Eigen::Matrix<double, 12, 1>::Zero();
  for (const ShapeAt& s : gauss_shapes()) {
    Vector3d x_xi = Vector3d::Zero(), x_eta = Vector3d::Zero();
    for (int b = 0; b < 4; ++b) {
      x_xi += s.dxi[b] * x[b];
      x_eta += s.deta[b] * x[b];
    }
    const Vector3d n_da = p * x_xi.cross(x_eta);  // p n dA per unit (xi, eta) area
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * a) += s.N[a] * n_da;
  }
  return f;
}

// d(x_xi x x_eta)/dx_b = N_b,eta skew(x_xi) - N_b,xi skew(x_eta).
Eigen::Matrix<double, 12, 12> pressure_load_stiffness(const std::array<Vector3d, 4>& x, double p) {
  Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero();
  for (const ShapeAt& s : gauss_shapes()) {
    Vector3d x_xi = Vector3d::Zero(), x_eta = Vector3d::Zero();
    for (int b = 0; b < 4; ++b) {
      x_xi += s.dxi[b] * x[b];
      x_eta += s.deta[b] * x[b];
    }
    const Matrix3d sxi = skew(x_xi), seta = skew(x_eta);
    for (int b = 0; b < 4; ++b) {
      const Matrix3d dn = p * (s.deta[b] * sxi - s.dxi[b] * seta);
      for (int a = 0; a < 4; ++a) k.block<3, 3>(3 * a, 3 * b) += s.N[a] * dn;
    }
  }
  return k;
}

}  // namespace si
