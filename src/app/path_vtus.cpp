#include "app/path_vtus.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/mode_field.hpp"
#include "io/damage_fields.hpp"
#include "io/result_fields.hpp"

namespace si {
namespace {

std::string numbered(const char* pattern, int index) {
  char name[32];
  std::snprintf(name, sizeof name, pattern, index);
  return name;
}

// Per-candidate values as a nodal field: zero at the nodes that are not candidates.
Eigen::VectorXd nodal_field(int num_nodes, const std::vector<int>& nodes,
                            const std::vector<double>& values) {
  Eigen::VectorXd field = Eigen::VectorXd::Zero(num_nodes);
  for (std::size_t i = 0; i < nodes.size(); ++i) field[nodes[i]] = values[i];
  return field;
}

}  // namespace

PathVtus::PathVtus(std::filesystem::path dir, const OutputSpec& output,
                   const IndentationSetup& setup, bool enabled)
    : dir_(std::move(dir)), output_(output), enabled_(enabled) {
  format_.encoding = output.vtu_encoding;
  format_.mirror_quarter = output.mirror && setup.model.symmetry_factor > 1;
}

void PathVtus::write(const std::string& name, const IndentationSetup& s, const IndentationState& st,
                     const cont::Vector& z, const Eigen::MatrixXd* mode) {
  const IndentationProblem& p = *s.problem;
  const std::vector<NodeState> state = p.node_states(z);
  VtuFields fields =
      resultant_fields(s.model.mesh, p.assembler(), *s.model.element, s.model.law, state);
  const int nn = s.model.mesh.num_nodes();
  fields.point_data["contact_pressure"] = nodal_field(nn, st.nodes, st.pressures);
  fields.point_data["contact_force"] = nodal_field(nn, st.nodes, st.multipliers);
  if (!st.frame_nodes.empty()) {  // a fixture's support frame: its reaction and gap per node
    fields.point_data["frame_force"] = nodal_field(nn, st.frame_nodes, st.frame_multipliers);
    fields.point_data["frame_gap"] = nodal_field(nn, st.frame_nodes, st.frame_gaps);
  }
  add_damage_fields(s, st, z, fields);
  if (mode != nullptr) {
    fields.point_data["critical_mode"] = *mode;
    fields.kinds["critical_mode"] = FieldKind::kVector;
  }
  write_vtu((dir_ / name).string(), s.model.mesh, state, fields, format_);
  frames_.emplace_back(st.depth, name);
}

void PathVtus::at_point(const IndentationSetup& setup, const PathPoint& p, const cont::Vector& z) {
  if (!enabled_) return;
  const int every = output_.vtu_every;
  const double tolerance = 1e-9 * setup.spec.path.depth_max;
  const bool requested = std::any_of(output_.at.begin(), output_.at.end(), [&](double d) {
    return std::abs(d - p.state.depth) <= tolerance;
  });
  if ((every > 0 && p.index % every == 0) || requested)
    write(numbered("path_%04d.vtu", p.index), setup, p.state, z);
}

int PathVtus::after_run(IndentationSetup& s, const PathResult& r) {
  if (!enabled_ || output_.vtu_every == 0) return 0;
  IndentationProblem& p = *s.problem;
  // The last point always has its fields (vtu_every counts points: a 0-10 mm run's last VTU was
  // at 6.22 mm).
  if (!r.points.empty() && r.final_unknowns.size() == p.size()) {
    const PathPoint& last = r.points.back();
    const std::string name = numbered("path_%04d.vtu", last.index);
    const bool written = std::any_of(frames_.begin(), frames_.end(),
                                     [&](const auto& f) { return f.second == name; });
    if (!written) write(name, s, p.evaluate(r.final_unknowns, last.state.depth), r.final_unknowns);
  }
  // The located events, at their own point. The problem may have grown its candidate set since
  // an event: in_present_layout puts the new multipliers (zero) before a local law's approach.
  int events = 0;
  for (const cont::Event& e : r.events) {
    if (!e.located || e.x.size() == 0) continue;
    const cont::Vector z = in_present_layout(e.x, p);
    if (z.size() == 0) continue;
    const std::string name = numbered("event_%02d.vtu", ++events);
    if (e.type == cont::EventType::kStabilityChange) {
      const Eigen::MatrixXd mode = mode_translations(p.dofs(), e.mode, s.model.mesh.num_nodes());
      write(name, s, p.evaluate(z, e.p), z, &mode);
    } else {
      write(name, s, p.evaluate(z, e.p), z);
    }
  }
  return events;
}

std::string PathVtus::pvd() const {
  std::vector<std::pair<double, std::string>> frames = frames_;
  std::stable_sort(frames.begin(), frames.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::ostringstream os;
  os.precision(12);  // the depth as path.csv writes it
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (i == 0 || frames[i].first != frames[i - 1].first)
      os << "  <DataSet timestep=\"" << frames[i].first << "\" file=\"" << frames[i].second
         << "\"/>\n";
  os << "</Collection>\n</VTKFile>\n";
  return os.str();
}

nlohmann::json PathVtus::record() const {
  nlohmann::json frames = nlohmann::json::array();
  for (const auto& [depth, name] : frames_) frames.push_back({depth, name});
  return frames;
}

void PathVtus::restore(const nlohmann::json& frames) {
  frames_.clear();
  for (const auto& f : frames)
    frames_.emplace_back(f.at(0).get<double>(), f.at(1).get<std::string>());
}

}  // namespace si
