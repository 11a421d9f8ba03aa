#include "io/damage_fields.hpp"

#include <sstream>

#include "io/spellings.hpp"

namespace si {
namespace {

std::vector<NodeDamage> evaluate_at(const IndentationSetup& setup, const IndentationState& state,
                                    const cont::Vector& z, const std::vector<int>& nodes) {
  const std::vector<NodeState> states = setup.problem->node_states(z);
  const Eigen::VectorXd pressures = Eigen::Map<const Eigen::VectorXd>(
      state.pressures.data(), static_cast<Eigen::Index>(state.pressures.size()));
  const Eigen::VectorXd forces = Eigen::Map<const Eigen::VectorXd>(
      state.multipliers.data(), static_cast<Eigen::Index>(state.multipliers.size()));
  return setup.damage->evaluate(ProbePoint{states, state.nodes, pressures, forces, state.force},
                                nodes);
}

std::string criterion_text(Criterion c) {
  return spelling(criterion_spellings(), c);
}

// The index of criterion `f` at recovered point `r` (ply criteria: its own point; the
// interlaminar one: the interface the point lies on, else empty).
std::string index_cell(const CriterionFailure& f, const RecoveredPoint& r, int position) {
  for (const FailurePoint& p : f.points) {
    const bool same =
        f.criterion == Criterion::kQuadraticDelamination
            ? (position == 0 && p.ply == r.ply) || (position == 2 && p.ply == r.ply + 1)
            : p.ply == r.ply && static_cast<int>(p.position) == position;
    if (same) {
      std::ostringstream os;
      os.precision(10);
      os << p.index.index;
      return os.str();
    }
  }
  return "";
}

}  // namespace

void add_damage_fields(const IndentationSetup& setup, const IndentationState& state,
                       const cont::Vector& z, VtuFields& fields) {
  if (!setup.damage) return;
  const int nodes = setup.model.mesh.num_nodes();
  const int plies = static_cast<int>(setup.spec.laminate.plies.size());
  const std::vector<NodeDamage> d = evaluate_at(setup, state, z, setup.damage->monitored());
  for (std::size_t c = 0; c < setup.damage->criteria().size(); ++c) {
    const Criterion criterion = setup.damage->criteria()[c];
    const bool interfaces = criterion == Criterion::kQuadraticDelamination;
    for (int k = interfaces ? 1 : 0; k < plies; ++k) {
      Eigen::MatrixXd values = Eigen::MatrixXd::Zero(nodes, interfaces ? 1 : 3);
      for (const NodeDamage& n : d)
        for (const FailurePoint& p : n.failure[c].points)
          if (p.ply == k)
            values(n.node, interfaces ? 0 : static_cast<int>(p.position)) = p.index.index;
      const std::string name =
          criterion_text(criterion) + "_index_" +
          (interfaces ? "interface" + std::to_string(k) : "ply" + std::to_string(k + 1));
      fields.point_data[name] = values;
    }
  }
}

std::string damage_points_header(const IndentationSetup& setup) {
  std::string h =
      "depth_mm,point,node,ply,position,x3_mm,s11_MPa,s12_MPa,s22_MPa,s13_MPa,s23_MPa,s33_MPa";
  if (setup.damage)
    for (Criterion c : setup.damage->criteria()) h += "," + criterion_text(c) + "_index";
  return h + "\n";
}

std::string damage_points_rows(const IndentationSetup& setup, const PathPoint& point,
                               const cont::Vector& z) {
  if (!setup.damage) return "";
  std::vector<int> nodes;
  for (const auto& r : setup.damage->reported()) nodes.push_back(r.second);
  const std::vector<NodeDamage> d = evaluate_at(setup, point.state, z, nodes);
  std::ostringstream os;
  os.precision(10);
  for (std::size_t k = 0; k < d.size(); ++k)
    for (std::size_t i = 0; i < d[k].recovered.size(); ++i) {
      const RecoveredPoint& r = d[k].recovered[i];
      const int position = static_cast<int>(i % 3);  // bottom, middle, top of each ply
      os << point.state.depth << ',' << setup.damage->reported()[k].first << ',' << d[k].node << ','
         << r.ply + 1 << ','
         << spelling(ply_position_spellings(), static_cast<PlyPosition>(position)) << ',' << r.x3;
      for (int s = 0; s < 6; ++s) os << ',' << r.stress[s];
      for (const CriterionFailure& f : d[k].failure) os << ',' << index_cell(f, r, position);
      os << '\n';
    }
  return os.str();
}

}  // namespace si
