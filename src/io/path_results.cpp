#include "io/path_results.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/path_columns.hpp"
#include "io/critical_points_json.hpp"
#include "io/damage_json.hpp"
#include "io/source_fingerprint.hpp"
#include "io/spellings.hpp"

namespace si {
namespace {

// Position of `name` in `names` (path.csv's columns, the monitors); -1 if absent.
template <class Names>
int index_of(const Names& names, const std::string& name) {
  int i = 0;
  for (const auto& n : names) {
    if (name == n) return i;
    ++i;
  }
  return -1;
}

// Element `name` of `values`, one per monitor (`monitors` order); NaN if absent.
double monitor_value(const Eigen::VectorXd& values, const std::vector<std::string>& monitors,
                     const std::string& name) {
  const int m = index_of(monitors, name);
  return m >= 0 && m < values.size() ? values[m] : std::nan("");
}

// The values at depth d inside the segment from a to b: cubic Hermite in the depth for the
// columns the table marks so (path_columns.hpp), where their slopes are known at both ends (error
// O(dh^4) where the branch is smooth, against O(dh^2) for the linear interpolation used
// otherwise). The work's slope is the force, and so is the strain energy's without a local law
// (dU/dh = T_N at equilibrium); the contact radius and area step from node to node, and the
// counts and residuals are no functions to interpolate: those stay linear.
std::vector<double> interpolate(const PathPoint& a, const PathPoint& b, double d,
                                const std::vector<std::string>& monitors,
                                const std::vector<PathColumn>& ids) {
  const double d0 = a.state.depth, dd = b.state.depth - d0, t = (d - d0) / dd;
  const std::vector<double> va = path_point_values(a, ids), vb = path_point_values(b, ids);
  std::vector<double> out(va.size());
  for (std::size_t c = 0; c < va.size(); ++c) out[c] = (1 - t) * va[c] + t * vb[c];
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  const auto hermite = [&](std::size_t c, double sa, double sb) {
    if (std::isfinite(sa) && std::isfinite(sb))
      out[c] = h00 * va[c] + h10 * dd * sa + h01 * vb[c] + h11 * dd * sb;
  };
  const std::size_t force = static_cast<std::size_t>(PathColumn::kForce);
  const std::size_t local = static_cast<std::size_t>(PathColumn::kLocalEnergy);
  std::vector<ColumnSpec> columns;
  for (PathColumn id : ids) columns.push_back(path_column(id));
  for (std::size_t c = 0; c < columns.size(); ++c) switch (columns[c].grid) {
      case GridInterpolation::kLinear:
        break;
      case GridInterpolation::kMinimum:
        out[c] = std::min(va[c], vb[c]);
        break;
      case GridInterpolation::kHermite:
        hermite(c, monitor_value(a.depth_slopes, monitors, columns[c].name),
                monitor_value(b.depth_slopes, monitors, columns[c].name));
        break;
      case GridInterpolation::kHermiteForceWithoutLocalLaw:
        if (va[local] != 0 || vb[local] != 0) break;
        [[fallthrough]];
      case GridInterpolation::kHermiteForce:
        hermite(c, va[force], vb[force]);
        break;
    }
  return out;
}

}  // namespace

const char* run_method_name(RunMethod method) {
  // In RunMethod's order.
  const char* const names[] = {"linear fast path", "active_set", "natural", "pseudo_arclength"};
  return names[static_cast<int>(method)];
}

const char* run_status_name(RunStatus status) {
  // In RunStatus's order.
  const char* const names[] = {"completed",      "reached_bound",       "max_steps",
                               "step_too_small", "stopped_by_callback", "start_failed",
                               "failed"};
  return names[static_cast<int>(status)];
}

std::string path_csv_header(const std::vector<PathColumn>& columns) {
  std::string h;
  for (PathColumn c : columns) h += (h.empty() ? "" : ",") + std::string(column_name(c));
  return h;
}

std::string path_csv(const PathResult& result) {
  std::ostringstream os;
  os.precision(12);
  os << path_csv_header(result_columns(result)) << '\n';
  const std::vector<PathColumn> columns = result_columns(result);
  for (const PathPoint& p : result.points) {
    const std::vector<double> v = path_point_values(p, columns);
    for (std::size_t i = 0; i < v.size(); ++i) os << (i ? "," : "") << v[i];
    os << '\n';
  }
  return os.str();
}

std::string path_grid_csv(const PathResult& result, double dh, double depth_max) {
  std::ostringstream os;
  os.precision(12);
  os << path_csv_header(result_columns(result)) << ",interpolated\n";
  const std::vector<PathColumn> columns = result_columns(result);
  const auto& pts = result.points;
  const int n = static_cast<int>(std::floor(depth_max / dh + 1e-9));
  for (int k = 0; k <= n; ++k) {
    const double d = k * dh;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double d0 = pts[i].state.depth;
      if (std::abs(d0 - d) <= 1e-9 * (1 + d)) {  // a converged point
        for (double v : path_point_values(pts[i], columns)) os << v << ',';
        os << "0\n";
        break;
      }
      if (i + 1 == pts.size()) break;
      const double d1 = pts[i + 1].state.depth;
      if ((d - d0) * (d - d1) < 0) {  // inside this segment: first passage
        for (double v : interpolate(pts[i], pts[i + 1], d, result.monitor_names, columns))
          os << v << ',';
        os << "1\n";
        break;
      }
    }
  }
  return os.str();
}

nlohmann::json events_json(const PathResult& result) {
  nlohmann::json events = nlohmann::json::array();
  for (std::size_t i = 0; i < result.events.size(); ++i) {
    const cont::Event& e = result.events[i];
    const auto at = [&](const char* name) {  // 0 for a monitor the event lacks
      const double v = monitor_value(e.monitors, result.monitor_names, name);
      return std::isnan(v) ? 0.0 : v;
    };
    events.push_back({{"type", e.name},
                      {"monitor", e.monitor},
                      {"against", e.against},
                      {column_name(PathColumn::kDepth), e.p},
                      {column_name(PathColumn::kForce), at(column_name(PathColumn::kForce))},
                      {column_name(PathColumn::kK11), at(column_name(PathColumn::kK11))},
                      {column_name(PathColumn::kK22), at(column_name(PathColumn::kK22))},
                      {"step", e.step},
                      {"located", e.located},
                      {"accuracy", e.accuracy}});
    nlohmann::json& event = events.back();
    if (e.type == cont::EventType::kStabilityChange) {
      // What changed and how (docs/theory/continuation.md 10); the mode is the event's VTU field.
      event["criticality"] = cont::criticality_name(e.criticality);
      event["negative_before"] = e.negative_before;
      event["negative_after"] = e.negative_after;
      event["eigenvalue"] =
          std::isfinite(e.eigenvalue) ? nlohmann::json(e.eigenvalue) : nlohmann::json(nullptr);
      event["tangent_depth"] = e.tangent_p;
    }
    for (const DamageOnset& o : result.damage.onsets)  // where and what the damage is
      if (o.event == static_cast<int>(i)) event.update(onset_json(o));
  }
  return events;
}

namespace {

// contact.local and its constants (docs/theory/local-indentation.md).
nlohmann::json local_contact_json(const IndentationSetup& setup) {
  const LocalContactLaw& law = setup.problem->local_law();
  const ContactSpec& contact = setup.spec.contact;
  nlohmann::json j = {{"law", spelling(local_contact_spellings(), contact.local)}};
  if (law.kind == LocalLawKind::kPowerLaw) {
    j["k_N_per_mm1.5"] = law.k;        // finite thickness: its Hertz form at small alpha
    j["dent_radius_mm"] = law.radius;  // hertz_dent.hpp; 0: uniform approach
  }
  if (contact.local == LocalContactModel::kAnisotropic) {
    j["support"] = spelling(local_support_spellings(), contact.local_support);
    j["plies"] = spelling(local_plies_spellings(), contact.local_plies);
  }
  if (law.layer) {
    j["modulus_MPa"] = law.layer->modulus();
    j["layer_thickness_mm"] = law.layer->thickness();
  }
  if (law.kind == LocalLawKind::kThinLayer) j["c_L_mm_per_MPa"] = law.compliance;
  return j;
}

}  // namespace

nlohmann::json imperfection_json(const ImperfectionSeed& s) {
  return {{"mode", s.spec.mode},
          {"amplitude_mm", s.spec.amplitude},
          {"taken_at", s.at_stability_change ? "stability_change" : "last_point"},
          {"criticality", cont::criticality_name(s.criticality)},
          {"depth_mm", s.depth},
          {"force_N", s.force},
          {"eigenvalue_N_per_mm", s.eigenvalue},
          {"perfect_points", s.perfect_points}};
}

std::string imperfection_summary(const ImperfectionSeed& s) {
  std::ostringstream o;
  o << "imperfection: mode " << s.spec.mode << " (eigenvalue " << s.eigenvalue << " N/mm) of the "
    << "perfect shell's restricted tangent at depth " << s.depth << " mm, "
    << (s.at_stability_change
            ? "its first stability change (" + cont::criticality_name(s.criticality) + ")"
            : std::string("the end of its path: no stability change on it"))
    << ", " << s.perfect_points << " points traced; added with amplitude " << s.spec.amplitude
    << " mm (largest nodal translation)";
  return o.str();
}

nlohmann::json path_json(const IndentationSetup& setup, const PathResult& result) {
  const ShellModel& m = setup.model;
  nlohmann::json points = nlohmann::json::array();
  for (const PathPoint& p : result.points) {
    nlohmann::json row;
    for (PathColumn id : result_columns(result))
      row[column_name(id)] = column_value(path_column(id), p);
    points.push_back(row);
  }
  nlohmann::json j = {
      {"case", setup.spec.file},
      {"build", {{"version", SHELLINDENT_VERSION}, {"source_fingerprint", source_fingerprint()}}},
      {"method", run_method_name(result.method)},
      {"element", m.element->name()},
      {"kinematics", spelling(kinematics_spellings(), m.kinematics)},
      {"nodes", m.mesh.num_nodes()},
      {"elements", m.mesh.num_elements()},
      {"shell_unknowns", setup.problem->num_shell_unknowns()},
      {"contact_candidates", setup.problem->candidates().size()},
      {"symmetry_factor", m.symmetry_factor},
      {"first_touch_travel_mm", setup.problem->first_touch()},
      {"local_contact", local_contact_json(setup)},
      {"note",
       "whole-shell values (a quarter model's forces, areas and energies times 4); depth = "
       "indenter travel after first touch; force along the direction of travel"},
      {"work",
       {{"residuals", setup.problem->counters().residuals},
        {"factorizations", setup.problem->counters().factorizations},
        {"solves", setup.problem->counters().solves},
        {"evaluations", setup.problem->counters().evaluations},
        {"stability_from_preconditioner", setup.problem->counters().stability_from_preconditioner},
        {"stability_direct", setup.problem->counters().stability_direct},
        {"preconditioner_factorizations", setup.problem->solver_counters().cholesky},
        {"lu_fallbacks", setup.problem->solver_counters().lu_fallbacks},
        {"preconditioner_ldlt_factorizations", setup.problem->solver_counters().ldlt},
        {"krylov_solves", setup.problem->solver_counters().krylov_solves},
        {"krylov_products", setup.problem->solver_counters().krylov_products}}},
      {"status", run_status_name(result.status)},
      {"completed", result.completed},
      {"reason", result.reason},
      {"points", points},
      {"events", events_json(result)},
      {"critical_points", critical_points_json(result.critical)}};
  if (setup.spec.damage) j["damage"] = damage_json(setup, result);
  if (setup.imperfection) j["imperfection"] = imperfection_json(*setup.imperfection);
  return j;
}

}  // namespace si
