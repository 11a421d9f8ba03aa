#include "analysis/path_columns.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace si {
namespace {

using G = GridInterpolation;
using S = IndentationState;

// Curvature component k (0: k11, 1: k12 + k21, 2: k22) of the extremes over the nodes in
// contact, and its inverse.
template <int k, bool largest>
double extreme(const S& s) {
  return largest ? s.contact_curvature_max[k] : s.contact_curvature_min[k];
}
template <int k, bool largest>
void restore_extreme(PathPoint& p, double v) {
  (largest ? p.state.contact_curvature_max : p.state.contact_curvature_min)[k] = v;
}

// The failure index of Criterion k (IndentationState::failure) and its inverse.
template <int k>
double failure_index(const S& s) {
  return s.failure[k].index;
}
template <int k>
void restore_failure_index(PathPoint& p, double v) {
  p.state.failure[k].index = v;
}

std::vector<ColumnSpec> make_columns() {
  std::vector<ColumnSpec> c = {
      {PathColumn::kDepth, "depth_mm", "mm",
       "h, the indenter's travel after first touch (the continuation parameter)",
       [](const S& s) { return s.depth; }, nullptr,
       [](PathPoint& p, double v) { p.state.depth = v; }},
      {PathColumn::kForce, "force_N", "N",
       "T_N, the sum of the contact multipliers: contact force along the direction of travel "
       "(`contact.traction: interpolated`: sum of t-bar_i w_i, the integral of the interpolated "
       "traction)",
       [](const S& s) { return s.force; }, nullptr,
       [](PathPoint& p, double v) { p.state.force = v; }, true, G::kHermite},
      {PathColumn::kReaction, "reaction_N", "N",
       "sum of the support reactions along the direction of travel (equals force_N at "
       "equilibrium)",
       [](const S& s) { return s.reaction; }, nullptr,
       [](PathPoint& p, double v) { p.state.reaction = v; }},
      {PathColumn::kApexDeflection, "apex_w_mm", "mm",
       "displacement of the apex mid-surface node along the direction of travel",
       [](const S& s) { return s.apex_deflection; }, nullptr,
       [](PathPoint& p, double v) { p.state.apex_deflection = v; }, true, G::kHermite},
      {PathColumn::kContactRadius, "contact_radius_mm", "mm",
       "largest distance of a node in contact from the apex's line of travel",
       [](const S& s) { return s.contact_radius; }, nullptr,
       [](PathPoint& p, double v) { p.state.contact_radius = v; }, true},
      {PathColumn::kContactArea, "contact_area_mm2", "mm^2",
       "sum of the tributary areas (a quarter of each adjacent element) of the nodes in contact",
       [](const S& s) { return s.contact_area; }, nullptr,
       [](PathPoint& p, double v) { p.state.contact_area = v; }},
      {PathColumn::kContactNodes, "contact_nodes", "-",
       "nodes with a positive multiplier (above 1e-9 of the largest); the model's nodes (not "
       "multiplied by the symmetry factor)",
       [](const S& s) { return static_cast<double>(s.contact_nodes); }, nullptr,
       [](PathPoint& p, double v) { p.state.contact_nodes = static_cast<int>(v); }},
      {PathColumn::kK11, "k11_per_mm", "1/mm",
       "curvature k11 at the apex node, averaged over its elements, in the laminate axes (x1 = "
       "global x projected on the surface)",
       [](const S& s) { return s.apex_curvature[0]; }, nullptr,
       [](PathPoint& p, double v) { p.state.apex_curvature[0] = v; }, true, G::kHermite},
      {PathColumn::kK12, "k12_per_mm", "1/mm", "curvature k12 + k21 at the apex node (as k11)",
       [](const S& s) { return s.apex_curvature[1]; }, nullptr,
       [](PathPoint& p, double v) { p.state.apex_curvature[1] = v; }, true, G::kHermite},
      {PathColumn::kK22, "k22_per_mm", "1/mm", "curvature k22 at the apex node (as k11)",
       [](const S& s) { return s.apex_curvature[2]; }, nullptr,
       [](PathPoint& p, double v) { p.state.apex_curvature[2] = v; }, true, G::kHermite},
      {PathColumn::kEnergy, "energy_Nmm", "N mm", "strain energy",
       [](const S& s) { return s.energy; }, nullptr,
       [](PathPoint& p, double v) { p.state.energy = v; }, false, G::kHermiteForceWithoutLocalLaw},
      {PathColumn::kWork, "work_Nmm", "N mm",
       "indenter work, trapezoidal integral of force_N over depth_mm (equals energy_Nmm + "
       "local_energy_Nmm to the integration error; with `hertz`/`yang_sun` while the contact "
       "stays within the Hertzian patch, otherwise less by the defect D of "
       "docs/theory/local-indentation.md 4)",
       nullptr, [](const PathPoint& p) { return p.work; },
       [](PathPoint& p, double v) { p.work = v; }, false, G::kHermiteForce},
      {PathColumn::kMinGap, "min_gap_mm", "mm",
       "smallest gap of the candidates (>= 0 up to the solver tolerance); with a local law, the "
       "gap to the locally indented face; interpolated traction: the weighted gaps over their "
       "weights, g~_i / w_i",
       [](const S& s) { return s.min_gap; }, nullptr,
       [](PathPoint& p, double v) { p.state.min_gap = v; }},
      {PathColumn::kMinMultiplier, "min_multiplier_N", "N",
       "smallest multiplier (>= 0 up to the tolerance); interpolated traction: of t-bar_i w_i",
       [](const S& s) { return s.min_multiplier; }, nullptr,
       [](PathPoint& p, double v) { p.state.min_multiplier = v; }},
      {PathColumn::kMaxComplementarity, "max_complementarity_Nmm", "N mm",
       "largest lambda_i g_i (interpolated traction: t-bar_i g~_i)",
       [](const S& s) { return s.max_complementarity; }, nullptr,
       [](PathPoint& p, double v) { p.state.max_complementarity = v; }},
      {PathColumn::kIterations, "iterations", "-", "Newton (or active-set) iterations of the point",
       nullptr, [](const PathPoint& p) { return static_cast<double>(p.iterations); },
       [](PathPoint& p, double v) { p.iterations = static_cast<int>(v); }},
      {PathColumn::kStep, "step", "mm",
       "the step that produced the point: depth step, or arclength step for pseudo_arclength",
       nullptr, [](const PathPoint& p) { return p.step; },
       [](PathPoint& p, double v) { p.step = v; }},
      {PathColumn::kLocalIndent, "local_indent_mm", "mm",
       "the local (through-thickness) approach of the indenter towards the contact face at the "
       "apex (`contact.local`; 0 for `none`): alpha of `hertz`/`yang_sun`, c_L++ p at the apex "
       "node for `vam`, sum_j C_apex,j lambda_j of the elastic face (`local_support: shell`). "
       "With the apex in contact, depth_mm = apex face deflection + "
       "local_indent_mm (docs/theory/local-indentation.md)",
       [](const S& s) { return s.local_indentation; }, nullptr,
       [](PathPoint& p, double v) { p.state.local_indentation = v; }},
      {PathColumn::kLocalEnergy, "local_energy_Nmm", "N mm",
       "energy of the local law: (2/5) k alpha^2.5 for `hertz`/`yang_sun`, sum of c_L lambda_i^2 "
       "/ (2 A_i) for `vam`, 1/2 lambda^T C lambda for the elastic face; work_Nmm = energy_Nmm + "
       "local_energy_Nmm to the integration error "
       "(power laws: see work_Nmm)",
       [](const S& s) { return s.local_energy; }, nullptr,
       [](PathPoint& p, double v) { p.state.local_energy = v; }},
  };
  // The extremes of the nodal curvatures over the nodes in contact (paper-notes item 7: the
  // paper's Figs 10-11 do not say where their curvatures are taken).
  const char* extremes =
      " over the nodes in contact (as at the apex; paper-notes item 7: the paper's Figs 10-11 do "
      "not say where their curvatures are taken); 0 without contact";
  const std::string descriptions[6] = {
      std::string("smallest nodal curvature k11") + extremes,
      std::string("largest nodal curvature k11") + extremes,
      std::string("smallest nodal curvature k12 + k21") + extremes +
          "; quarter models: -max abs(k12), its sign flipping in the mirrored quadrants",
      std::string("largest nodal curvature k12 + k21") + extremes +
          "; quarter models: max abs(k12)",
      std::string("smallest nodal curvature k22") + extremes,
      std::string("largest nodal curvature k22") + extremes};
  const char* const names[6] = {"k11_contact_min_per_mm", "k11_contact_max_per_mm",
                                "k12_contact_min_per_mm", "k12_contact_max_per_mm",
                                "k22_contact_min_per_mm", "k22_contact_max_per_mm"};
  double (*const value[6])(const S&) = {extreme<0, false>, extreme<0, true>,  extreme<1, false>,
                                        extreme<1, true>,  extreme<2, false>, extreme<2, true>};
  void (*const restore[6])(PathPoint&, double) = {
      restore_extreme<0, false>, restore_extreme<0, true>,  restore_extreme<1, false>,
      restore_extreme<1, true>,  restore_extreme<2, false>, restore_extreme<2, true>};
  for (int i = 0; i < 6; ++i)
    c.push_back({static_cast<PathColumn>(static_cast<int>(PathColumn::kK11ContactMin) + i),
                 names[i], "1/mm", descriptions[i], value[i], nullptr, restore[i]});
  c.push_back(
      {PathColumn::kErrorEstimate, "error_estimate", "-",
       "estimated relative discretisation error of the point in the energy norm "
       "(Zienkiewicz-Zhu recovery of the shell's generalised strains over the whole mesh, "
       "docs/theory/discretisation-error.md): how good the strain field is; it does not bound "
       "the force's error at a contact (the force converges faster). Compare with "
       "`mesh.tolerance`",
       [](const S& s) { return s.error_estimate; }, nullptr,
       [](PathPoint& p, double v) { p.state.error_estimate = v; }});
  c.push_back({PathColumn::kFrameForce, "frame_force_N", "N",
               "force the support frame of a `fixture` carries along its normal (whole plate; "
               "part of reaction_N, with the clamps' reactions making up the rest); 0 without "
               "a fixture",
               [](const S& s) { return s.frame_force; }, nullptr,
               [](PathPoint& p, double v) { p.state.frame_force = v; }});
  c.push_back({PathColumn::kApexMidDeflection, "apex_mid_w_mm", "mm",
               "the laminate's apex mid-plane displacement along the direction of travel: "
               "apex_w_mm plus, with the elastic face (`local_support: shell`), the exact "
               "plate's mid-plane less the shell's Reissner-Mindlin deflection under the contact "
               "forces (the shell's deflection under a concentrated load carries its shear "
               "excess; docs/theory/local-indentation.md 6.10); apex_w_mm otherwise",
               [](const S& s) { return s.apex_mid_deflection; }, nullptr,
               [](PathPoint& p, double v) { p.state.apex_mid_deflection = v; }});
  ColumnSpec force_error{
      PathColumn::kForceError,
      "force_error_estimate",
      "-",
      "estimated relative discretisation error of force_N, from a companion run on the mesh "
      "with twice the element sizes at the same depths: abs(F - F_2h) / (3 F), the Richardson "
      "estimate of an error of order 2 (written with `mesh.error_estimate: companion`; "
      "docs/theory/discretisation-error.md says where it holds)",
      nullptr,
      [](const PathPoint& p) { return p.force_error; },
      [](PathPoint& p, double v) { p.force_error = v; }};
  force_error.group = ColumnGroup::kCompanionMesh;
  c.push_back(force_error);
  // The failure indices (analysis/damage_probe.hpp): the largest over the monitored nodes.
  // path_grid.csv interpolates them linearly: a largest value over nodes and plies has a kink
  // wherever its place changes, where a slope is no better than the chord, and each point's
  // slopes would cost two more probes off the branch (issue 16's budget).
  const std::string index =
      " over the monitored nodes near the indenter (bottom, middle and top of every ply; "
      "docs/theory/failure.md 6): the inverse load factor to onset, 1 = onset (an event "
      "`damage_onset` in events.json and path.json's `damage`)";
  c.push_back({PathColumn::kMaxStressIndex, "max_stress_index", "-",
               "largest maximum-stress failure index" + index, failure_index<0>, nullptr,
               restore_failure_index<0>, true, G::kLinear, Criterion::kMaxStress});
  c.push_back({PathColumn::kTsaiWuIndex, "tsai_wu_index", "-",
               "largest Tsai-Wu failure index" + index, failure_index<1>, nullptr,
               restore_failure_index<1>, true, G::kLinear, Criterion::kTsaiWu});
  c.push_back({PathColumn::kHashinIndex, "hashin_index", "-",
               "largest Hashin (3-D, four modes) failure index" + index, failure_index<2>, nullptr,
               restore_failure_index<2>, true, G::kLinear, Criterion::kHashin});
  c.push_back({PathColumn::kDelaminationIndex, "delamination_index", "-",
               "largest quadratic interlaminar (Brewer-Lagace) index on the interfaces" + index,
               failure_index<3>, nullptr, restore_failure_index<3>, true, G::kLinear,
               Criterion::kQuadraticDelamination});
  // The stability of the point (path.stability; docs/theory/continuation.md 9, 12).
  ColumnSpec stable{PathColumn::kStable,
                    "stable",
                    "-",
                    "1 if the point is a stable equilibrium on its contact set: the tangent "
                    "restricted to the directions that keep the pressing contacts has no "
                    "negative and no numerically zero eigenvalue; else 0 (written with "
                    "`path.stability: true`; path_grid.csv: 1 only between two stable points)",
                    nullptr,
                    [](const PathPoint& p) { return p.stable ? 1.0 : 0.0; },
                    [](PathPoint& p, double v) { p.stable = v != 0; }};
  stable.grid = G::kMinimum;
  stable.group = ColumnGroup::kStability;
  ColumnSpec lowest{PathColumn::kLowestEigenvalue,
                    "lowest_eigenvalue",
                    "N/mm",
                    "lowest eigenvalue of that restricted tangent (the Hessian of the energy in "
                    "the shell's chart coordinates, mm and rad, so N/mm for a mode of "
                    "translations); it crosses zero where the point loses stability (written "
                    "with `path.stability: true`)",
                    nullptr,
                    [](const PathPoint& p) { return p.lowest_eigenvalue; },
                    [](PathPoint& p, double v) { p.lowest_eigenvalue = v; }};
  lowest.group = ColumnGroup::kStability;
  ColumnSpec branch{PathColumn::kBranch,
                    "branch",
                    "-",
                    "the branch the point lies on: 0 the fundamental path, 1 the branch switched "
                    "to at its first bifurcation (`path.branch_switch`; written with "
                    "`path.stability: true`; path_grid.csv: the smaller end)",
                    nullptr,
                    [](const PathPoint& p) { return static_cast<double>(p.branch); },
                    [](PathPoint& p, double v) { p.branch = static_cast<int>(v); }};
  branch.grid = G::kMinimum;
  branch.group = ColumnGroup::kStability;
  c.push_back(stable);
  c.push_back(lowest);
  c.push_back(branch);
  for (std::size_t i = 0; i < c.size(); ++i)
    SI_ASSERT(static_cast<std::size_t>(c[i].id) == i);  // the table is in PathColumn's order
  return c;
}

}  // namespace

const std::vector<ColumnSpec>& path_columns() {
  static const std::vector<ColumnSpec> columns = make_columns();
  return columns;
}

const ColumnSpec& path_column(PathColumn id) {
  return path_columns()[static_cast<std::size_t>(id)];
}

const char* column_name(PathColumn id) {
  return path_column(id).name;
}

double column_value(const ColumnSpec& c, const PathPoint& p) {
  return c.of_state ? c.of_state(p.state) : c.of_point(p);
}

std::vector<PathColumn> run_columns(const std::vector<Criterion>& monitored, bool stability,
                                    bool companion) {
  std::vector<PathColumn> out;
  for (const ColumnSpec& c : path_columns()) {
    if ((c.group == ColumnGroup::kStability && !stability) ||
        (c.group == ColumnGroup::kCompanionMesh && !companion))
      continue;
    if (!c.criterion ||
        std::find(monitored.begin(), monitored.end(), *c.criterion) != monitored.end())
      out.push_back(c.id);
  }
  return out;
}

std::vector<PathColumn> result_columns(const PathResult& r) {
  return run_columns(r.criteria, r.stability, r.companion_mesh);
}

const std::vector<PathColumn>& base_columns() {
  static const std::vector<PathColumn> columns = run_columns({});
  return columns;
}

PathColumn failure_column(Criterion criterion) {
  for (const ColumnSpec& c : path_columns())
    if (c.criterion == criterion) return c.id;
  SI_ASSERT(false);  // every criterion has its column
  return PathColumn::kDepth;
}

std::vector<double> path_point_values(const PathPoint& p, const std::vector<PathColumn>& columns) {
  std::vector<double> v;
  for (PathColumn c : columns) v.push_back(column_value(path_column(c), p));
  return v;
}

PathPoint path_point_from_values(const std::vector<double>& v,
                                 const std::vector<PathColumn>& columns) {
  SI_REQUIRE(v.size() == columns.size(),
             "a path point has " + std::to_string(columns.size()) + " values");
  PathPoint p;
  for (std::size_t i = 0; i < columns.size(); ++i) path_column(columns[i]).restore(p, v[i]);
  return p;
}

std::vector<StateMonitor> path_monitors(const std::vector<PathColumn>& columns) {
  std::vector<StateMonitor> m;
  for (PathColumn id : columns) {
    const ColumnSpec& c = path_column(id);
    if (c.monitor) m.push_back({c.name, c.of_state, c.criterion.has_value()});
  }
  return m;
}

std::vector<std::string> slope_monitor_names(const std::vector<PathColumn>& columns) {
  std::vector<std::string> names;
  for (PathColumn id : columns) {
    const ColumnSpec& c = path_column(id);
    if (c.monitor && c.grid == GridInterpolation::kHermite) names.emplace_back(c.name);
  }
  return names;
}

Eigen::VectorXd monitor_values(const IndentationState& s, const std::vector<PathColumn>& columns) {
  std::vector<double> v;
  for (PathColumn id : columns) {
    const ColumnSpec& c = path_column(id);
    if (c.monitor) v.push_back(c.of_state(s));
  }
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

}  // namespace si
