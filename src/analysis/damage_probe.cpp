#include "analysis/damage_probe.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "model/patch_fit.hpp"

namespace si {
namespace {

// The plan's patch (docs/theory/failure.md 6 item 2): a cubic over the 25 nearest nodes.
constexpr int kPatchDegree = 3;
constexpr int kPatchNodes = 25;
// Bottom, middle and top of every ply: what ThroughThicknessFailure::evaluate reads.
constexpr int kPointsPerPly = 3;

int nearest_node(const Mesh& mesh, const Vector3d& x) {
  int best = 0;
  for (int n = 1; n < mesh.num_nodes(); ++n)
    if ((mesh.nodes[n] - x).squaredNorm() < (mesh.nodes[best] - x).squaredNorm()) best = n;
  return best;
}

// The tangent plane's axes at a node: t1 = global x projected on it (the elements' x1, so the
// laminate's angles hold), or global y where x is nearly normal to the surface.
std::pair<Vector3d, Vector3d> tangent_axes(const Vector3d& director) {
  Vector3d t1 = Vector3d::UnitX() - director.x() * director;
  if (t1.norm() < 1e-3) t1 = Vector3d::UnitY() - director.y() * director;
  t1.normalize();
  return {t1, director.cross(t1)};
}

// Monitored: the apex, the reported points, and the candidates or the nodes within `radius` of
// the apex's line of travel.
std::vector<int> monitored_nodes(const ShellModel& model, const DamageSpec& spec, const Vector3d& e,
                                 const std::vector<int>& candidates,
                                 const std::vector<std::pair<std::string, int>>& reported) {
  std::set<int> nodes;
  for (const auto& r : reported) nodes.insert(r.second);
  if (spec.radius > 0) {
    const Vector3d& apex = model.mesh.nodes[model.apex_node()];
    for (int n = 0; n < model.mesh.num_nodes(); ++n) {
      const Vector3d d = model.mesh.nodes[n] - apex;
      if ((d - d.dot(e) * e).norm() <= spec.radius) nodes.insert(n);
    }
  } else {
    nodes.insert(candidates.begin(), candidates.end());
  }
  return {nodes.begin(), nodes.end()};
}

}  // namespace

DamageProbe::DamageProbe(const ShellModel& model, const Assembler& assembler,
                         const Laminate& laminate, const DamageSpec& spec,
                         const Vector3d& direction, const std::vector<int>& candidates,
                         const LocalContactLaw& face_law)
    : model_(model),
      assembler_(assembler),
      spec_(spec),
      section_(analyze_vam(laminate)),
      failure_(laminate, spec.criteria),
      face_law_(face_law),
      direction_(direction.normalized()) {
  const double patch_radius = spec.patch_radius < 0 ? 2 * laminate.thickness() : spec.patch_radius;
  const int apex = model.apex_node();
  loaded_sign_ = direction.dot(model.mesh.directors[apex]) <= 0 ? 1.0 : -1.0;
  reported_.push_back({"apex", apex});
  for (const DamagePoint& p : spec.points)
    reported_.push_back({p.name, nearest_node(model.mesh, p.position)});
  monitored_ = monitored_nodes(model, spec, direction, candidates, reported_);
  monitored_index_.assign(model.mesh.num_nodes(), -1);
  for (std::size_t k = 0; k < monitored_.size(); ++k)
    monitored_index_[monitored_[k]] = static_cast<int>(k);
  // The patches, and the nodes and elements whose strains they read.
  std::vector<int> row(model.mesh.num_nodes(), -1);
  std::vector<std::vector<int>> nearest;
  for (int node : monitored_) {
    std::vector<int> order(model.mesh.num_nodes());
    std::iota(order.begin(), order.end(), 0);
    const Vector3d& x = model.mesh.nodes[node];
    const auto closer = [&](int a, int b) {
      return (model.mesh.nodes[a] - x).squaredNorm() < (model.mesh.nodes[b] - x).squaredNorm();
    };
    // Every node within the radius, or the 25 nearest where fewer lie within it: O(N) per node
    // (a full sort of the mesh per monitored node would cost seconds on 1e5 nodes).
    const auto within = std::partition(order.begin(), order.end(), [&](int n) {
      return (model.mesh.nodes[n] - x).norm() <= patch_radius;
    });
    int count = static_cast<int>(within - order.begin());
    if (count < kPatchNodes) {
      count = std::min(kPatchNodes, model.mesh.num_nodes());
      std::partial_sort(order.begin(), order.begin() + count, order.end(), closer);
    }
    order.resize(count);
    for (int n : order)
      if (row[n] < 0) {
        row[n] = static_cast<int>(strain_nodes_.size());
        strain_nodes_.push_back(n);
      }
    nearest.push_back(order);
  }
  for (std::size_t k = 0; k < monitored_.size(); ++k) {
    Patch p;
    const Vector3d& x = model.mesh.nodes[monitored_[k]];
    const auto [t1, t2] = tangent_axes(model.mesh.directors[monitored_[k]]);
    std::vector<Vector2d> coords;
    for (int n : nearest[k]) {
      p.rows.push_back(row[n]);
      const Vector3d d = model.mesh.nodes[n] - x;
      coords.emplace_back(d.dot(t1), d.dot(t2));
    }
    const int count = static_cast<int>(coords.size());
    const PatchFit unit = fit_patch(coords, Eigen::MatrixXd::Identity(count, count),
                                    Vector2d::Zero(), kPatchDegree, count);
    p.fit.resize(10, count);
    p.fit.row(0) = unit.value.transpose();
    for (int i = 0; i < 2; ++i) p.fit.row(1 + i) = unit.d1[i].transpose();
    for (int i = 0; i < 3; ++i) p.fit.row(3 + i) = unit.d2[i].transpose();
    for (int i = 0; i < 4; ++i) p.fit.row(6 + i) = unit.d3[i].transpose();
    patches_.push_back(std::move(p));
  }
  build_recovery_map();
  for (int e = 0; e < model.mesh.num_elements(); ++e)
    for (int n : model.mesh.elements[e])
      if (row[n] >= 0) {
        strain_elements_.push_back(e);
        break;
      }
}

// The element-averaged nodal strains (model/nodal_resultants.hpp's average), each element
// evaluated once.
Eigen::MatrixXd DamageProbe::patch_strains(const std::vector<NodeState>& states) const {
  const Eigen::Index rows = static_cast<Eigen::Index>(strain_nodes_.size());
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(rows, 6);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(rows);
  std::vector<int> row(model_.mesh.num_nodes(), -1);
  for (std::size_t i = 0; i < strain_nodes_.size(); ++i)
    row[strain_nodes_[i]] = static_cast<int>(i);
  for (int e : strain_elements_) {
    const ElementStrains s = model_.element->strains_at_nodes(
        assembler_.geometry(e), assembler_.element_states(states, e), assembler_.kinematics());
    for (int a = 0; a < 4; ++a) {
      const int r = row[model_.mesh.elements[e][a]];
      if (r < 0) continue;
      sum.row(r) += s.R[a].transpose();
      count[r] += 1;
    }
  }
  for (Eigen::Index r = 0; r < rows; ++r)
    if (count[r] > 0) sum.row(r) /= count[r];
  return sum;
}

double DamageProbe::axial_distance(int n) const {
  const Vector3d d = model_.mesh.nodes[n] - model_.mesh.nodes[model_.apex_node()];
  return (d - d.dot(direction_) * direction_).norm();
}

// Hertz (point-loads.md 4.3; Johnson 1985, 4.2): with F = (4/3) E* R^0.5 alpha^1.5 = k
// alpha^1.5, the contact radius a = (3 F R / (4 E*))^(1/3) = (F R^1.5 / k)^(1/3) and the pressure
// p0 sqrt(1 - r^2 / a^2), p0 = 3 F / (2 pi a^2). Where the shell model's own contact patch is
// wider (a conforming contact, several nodes pressed) its radius is taken, with the same total
// force and shape: what the mesh resolves is kept, what it cannot is Hertz's. The patch's radius
// is measured by the nodal forces' second moment, which for Hertz's pressure is <r^2> = (2/5)
// a^2: it grows continuously from 0 as a ring of nodes starts to bear (the farthest pressed node
// would jump to the ring's radius, the element size, at its first touch).
std::vector<double> DamageProbe::hertz_pressures(const ProbePoint& point) const {
  std::vector<double> p(monitored_.size(), 0.0);
  if (!(point.force > 0)) return p;
  double moment = 0, total = 0;
  for (std::size_t i = 0; i < point.candidates.size(); ++i) {
    const double f = point.forces[static_cast<Eigen::Index>(i)];
    if (!(f > 0)) continue;
    const double r = axial_distance(point.candidates[i]);
    moment += f * r * r;
    total += f;
  }
  const double a_patch = total > 0 ? std::sqrt(2.5 * moment / total) : 0.0;
  const double a =
      std::max(std::cbrt(point.force * std::pow(face_law_.radius, 1.5) / face_law_.k), a_patch);
  const double p0 = 3 * point.force / (2 * kPi * a * a);
  for (std::size_t k = 0; k < monitored_.size(); ++k) {
    const double r = axial_distance(monitored_[k]);
    if (r < a) p[k] = p0 * std::sqrt(1 - r * r / (a * a));
  }
  return p;
}

std::vector<double> DamageProbe::monitored_pressures(const ProbePoint& point) const {
  if (spec_.face_pressure == FacePressure::kHertz && face_law_.kind == LocalLawKind::kPowerLaw)
    return hertz_pressures(point);
  std::vector<double> p(monitored_.size(), 0.0);
  for (std::size_t i = 0; i < point.candidates.size(); ++i) {
    const int k = monitored_index_[point.candidates[i]];
    if (k >= 0) p[k] = std::max(point.pressures[static_cast<Eigen::Index>(i)], 0.0);
  }
  return p;
}

namespace {

// The number of recovery inputs (recovery_map_'s columns): R, R,1, R,2, then (refined) R,11
// R,12 R,22 R,111 R,112 R,122 R,222 (Patch::fit's rows), then t+ and t-.
int recovery_inputs(StressRecovery recovery) {
  return (recovery == StressRecovery::kRefined ? 10 : 3) * 6 + 2;
}

// A unit input j (recovery_inputs' order) as a plate state.
PlateState unit_state(int j, int inputs, bool refined) {
  PlateState unit;
  std::array<Vector6d, 3> d2;
  std::array<Vector6d, 4> d3;
  for (auto& v : d2) v.setZero();
  for (auto& v : d3) v.setZero();
  const int block = j / 6, entry = j % 6;
  if (j == inputs - 2) {
    unit.t_top = 1;
  } else if (j == inputs - 1) {
    unit.t_bottom = 1;
  } else if (block == 0) {
    unit.R[entry] = 1;
  } else if (block < 3) {
    unit.dR[block - 1][entry] = 1;
  } else if (block < 6) {
    d2[block - 3][entry] = 1;
  } else {
    d3[block - 6][entry] = 1;
  }
  if (refined) {
    unit.d2R = d2;
    unit.d3R = d3;
  }
  return unit;
}

}  // namespace

void DamageProbe::build_recovery_map() {
  const bool refined = spec_.recovery == StressRecovery::kRefined;
  const int inputs = recovery_inputs(spec_.recovery);
  for (int j = 0; j < inputs; ++j) {
    const std::vector<RecoveredPoint> r = recover_through_thickness(
        section_, unit_state(j, inputs, refined), kPointsPerPly, EquilibriumCheck::kSkipped);
    if (j == 0) {
      recovery_map_ = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(r.size()), inputs);
      recovered_template_ = r;
    }
    for (std::size_t i = 0; i < r.size(); ++i)
      recovery_map_.block<6, 1>(6 * static_cast<Eigen::Index>(i), j) = r[i].stress;
  }
  for (RecoveredPoint& p : recovered_template_) {
    p.strain.setZero();
    p.stress.setZero();
    p.warping.setZero();
  }
}

NodeDamage DamageProbe::at_node(int k, const Eigen::MatrixXd& strains, double pressure) const {
  const Patch& patch = patches_[k];
  Eigen::MatrixXd values(static_cast<Eigen::Index>(patch.rows.size()), 6);
  for (std::size_t i = 0; i < patch.rows.size(); ++i)
    values.row(static_cast<Eigen::Index>(i)) = strains.row(patch.rows[i]);
  const Eigen::MatrixXd derivatives = patch.fit * values;  // 10 x 6
  const int inputs = static_cast<int>(recovery_map_.cols());
  Eigen::VectorXd in(inputs);
  for (int block = 0; block < (inputs - 2) / 6; ++block)
    in.segment<6>(6 * block) = derivatives.row(block).transpose();
  // The indenter presses its face: t+ = -p on the top face, t- = +p on the bottom (along +x3).
  in[inputs - 2] = loaded_sign_ > 0 ? -pressure : 0.0;
  in[inputs - 1] = loaded_sign_ > 0 ? 0.0 : pressure;
  const Eigen::VectorXd stress = recovery_map_ * in;
  NodeDamage d;
  d.node = monitored_[k];
  d.recovered = recovered_template_;
  for (std::size_t i = 0; i < d.recovered.size(); ++i)
    d.recovered[i].stress = stress.segment<6>(6 * static_cast<Eigen::Index>(i));
  d.failure = failure_.evaluate(d.recovered);
  return d;
}

void DamageProbe::measure(const ProbePoint& point, IndentationState& out) const {
  const Eigen::MatrixXd strains = patch_strains(point.states);
  const std::vector<double> pressure = monitored_pressures(point);
  for (Criterion c : spec_.criteria) out.failure[static_cast<int>(c)] = MonitoredFailure{0.0};
  for (std::size_t k = 0; k < monitored_.size(); ++k) {
    const NodeDamage d = at_node(static_cast<int>(k), strains, pressure[k]);
    for (const CriterionFailure& f : d.failure) {
      MonitoredFailure& m = out.failure[static_cast<int>(f.criterion)];
      if (!(f.governing.index.index > m.index)) continue;
      m.index = f.governing.index.index;
      m.mode = f.governing.index.mode;
      m.ply = f.governing.ply;
      m.position = f.governing.position;
      m.interface = f.criterion == Criterion::kQuadraticDelamination;
      m.x3 = f.governing.x3;
      m.node = d.node;
    }
  }
}

std::vector<NodeDamage> DamageProbe::evaluate(const ProbePoint& point,
                                              const std::vector<int>& nodes) const {
  const Eigen::MatrixXd strains = patch_strains(point.states);
  const std::vector<double> pressure = monitored_pressures(point);
  std::vector<NodeDamage> out;
  for (int n : nodes) {
    const int k = monitored_index_[n];
    SI_REQUIRE(k >= 0, "damage: node " + std::to_string(n) + " is not monitored");
    out.push_back(at_node(k, strains, pressure[k]));
  }
  return out;
}

}  // namespace si
