#include "app/static_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "analysis/static_run.hpp"
#include "app/interrupt_signals.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/case_file.hpp"
#include "io/case_key_location.hpp"
#include "io/output_directory.hpp"
#include "io/output_lock.hpp"
#include "io/result_fields.hpp"
#include "io/thread_count.hpp"
#include "io/vtu_writer.hpp"
#include "model/node_set.hpp"
#include "model/shell_model.hpp"

namespace si {
namespace {

// One row of the output, whole-shell values (a quarter model's forces and energy times 4).
struct StaticRow {
  double load_factor = 0;
  double force = 0;       // N, applied, along -z (resultant of the nodal loads)
  double deflection = 0;  // mm, apex, along -z
  double energy = 0;      // N mm, strain energy
  double reaction = 0;    // N, sum of the support reactions along +z
  int iterations = 0;
  std::vector<Vector3d> recorded;  // mm, the mean displacement of each static.record set
  // static.stability only (negative = -1 otherwise): negative eigenvalues, stable, lowest one.
  int negative = -1;
  bool stable = false;
  double lowest_eigenvalue = 0;
};

// static.record: the recorded sets' names and, for each, the positions of its nodes in
// StepResult::displacements (after the apex, position 0).
struct RecordedSets {
  std::vector<std::string> names;
  std::vector<std::vector<int>> positions;
};

StaticRow make_row(const StepResult& r, double factor, const RecordedSets& sets) {
  StaticRow row{r.load_factor,
                -factor * r.applied_force.z(),
                -r.displacements[0].z(),
                factor * r.energy,
                factor * r.reaction_force.z(),
                r.iterations,
                {},
                r.negative_eigenvalues,
                r.stable,
                r.lowest_eigenvalue};
  for (const std::vector<int>& positions : sets.positions) {
    Vector3d sum = Vector3d::Zero();
    for (int i : positions) sum += r.displacements[i];
    row.recorded.push_back(sum / static_cast<double>(positions.size()));
  }
  return row;
}

// Adds the nodes of the static.record sets to settings.record_nodes; an unknown set is an input
// error at static.record with the case file's line.
RecordedSets record_sets(const CaseFile& c, const Mesh& mesh, const std::string& text,
                         StaticSettings& settings) {
  RecordedSets sets;
  for (const std::string& name : c.static_record) {
    const std::vector<int>* nodes = nullptr;
    try {
      nodes = &find_node_set(mesh, name, "record");
    } catch (const Error& e) {
      throw located_in_case(Error(e.kind(), e.reason(), Where{c.file, "static.record", name, 0}),
                            text);
    }
    sets.names.push_back(name);
    sets.positions.emplace_back();
    for (int node : *nodes) {
      sets.positions.back().push_back(static_cast<int>(settings.record_nodes.size()));
      settings.record_nodes.push_back(node);
    }
  }
  return sets;
}

std::string format_row(const StaticRow& r) {
  char line[200];
  std::snprintf(line, sizeof line, "%8.4f %14.6g %14.6g %16.6g %14.6g %6d", r.load_factor, r.force,
                r.deflection, r.energy, r.reaction, r.iterations);
  return line;
}

// The columns of a recorded set: <name>_ux_mm, <name>_uy_mm, <name>_uz_mm.
std::string recorded_column(const std::string& name, int axis) {
  return name + "_u" + "xyz"[axis] + "_mm";
}

// With static.stability two more columns: stable (0/1) and lowest_eigenvalue (N/mm).
std::string csv_text(const std::vector<StaticRow>& rows, const RecordedSets& sets, bool stability) {
  std::ostringstream os;
  os.precision(12);
  os << "load_factor,force_N,apex_deflection_mm,strain_energy_Nmm,reaction_N,iterations";
  for (const std::string& name : sets.names)
    for (int axis = 0; axis < 3; ++axis) os << ',' << recorded_column(name, axis);
  os << (stability ? ",stable,lowest_eigenvalue" : "") << '\n';
  for (const auto& r : rows) {
    os << r.load_factor << ',' << r.force << ',' << r.deflection << ',' << r.energy << ','
       << r.reaction << ',' << r.iterations;
    for (const Vector3d& u : r.recorded) os << ',' << u.x() << ',' << u.y() << ',' << u.z();
    if (stability) os << ',' << (r.stable ? 1 : 0) << ',' << r.lowest_eigenvalue;
    os << '\n';
  }
  return os.str();
}

nlohmann::json json_of(const StaticRow& r, const RecordedSets& sets) {
  nlohmann::json j{{"load_factor", r.load_factor},       {"force_N", r.force},
                   {"apex_deflection_mm", r.deflection}, {"strain_energy_Nmm", r.energy},
                   {"reaction_N", r.reaction},           {"iterations", r.iterations}};
  for (std::size_t i = 0; i < sets.names.size(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      j[recorded_column(sets.names[i], axis)] = r.recorded[i][axis];
  if (r.negative >= 0) {
    j["stable"] = r.stable;
    j["negative_eigenvalues"] = r.negative;
    j["lowest_eigenvalue"] = r.lowest_eigenvalue;
  }
  return j;
}

// A located event of the run (a limit point of the load factor), with the values there.
struct StaticEventRow {
  cont::EventType type;
  StaticRow row;
  cont::Criticality criticality = cont::Criticality::kNone;
  int negative_before = -1, negative_after = -1;
};

nlohmann::json json_of(const CaseFile& c, const ShellModel& m, const DofMap& dofs,
                       const std::vector<StaticRow>& rows,
                       const std::vector<StaticEventRow>& event_rows, const RecordedSets& sets,
                       const std::string& failure) {
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& r : rows) steps.push_back(json_of(r, sets));
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : event_rows) {
    nlohmann::json j = json_of(e.row, sets);
    j.erase("iterations");
    j["type"] = cont::event_type_name(e.type);
    if (e.type == cont::EventType::kStabilityChange) {
      j["criticality"] = cont::criticality_name(e.criticality);
      j["negative_before"] = e.negative_before;
      j["negative_after"] = e.negative_after;
    }
    events.push_back(j);
  }
  return {{"case", c.file},
          {"method", c.static_run.method == PathMethod::kNatural ? "natural" : "pseudo_arclength"},
          {"element", m.element->name()},
          {"kinematics", m.kinematics == Kinematics::kLinear ? "linear" : "nonlinear"},
          {"nodes", m.mesh.num_nodes()},
          {"elements", m.mesh.num_elements()},
          {"free_dofs", dofs.num_free()},
          {"symmetry_factor", m.symmetry_factor},
          {"note",
           "whole-shell values: a quarter model's forces and energy are multiplied by 4; "
           "force and deflection along -z, reaction along +z"},
          {"status", failure.empty() ? "completed" : "failed"},
          {"failure", failure},
          {"steps", steps},
          {"events", events}};
}

bool wants(const OutputSpec& output, OutputFormat format) {
  return std::find(output.formats.begin(), output.formats.end(), format) != output.formats.end();
}

// The files of output.formats: static.csv, static.json, static.vtu.
void write_results(const std::filesystem::path& dir, const ShellModel& m, const OutputSpec& output,
                   const Assembler& assembler, const std::vector<NodeState>* last_state,
                   const std::string& csv, const std::string& json, std::ostream& err) {
  std::vector<std::string> written;
  if (wants(output, OutputFormat::kCsv)) {
    write_file_atomically((dir / "static.csv").string(), csv);
    written.push_back((dir / "static.csv").string());
  }
  if (wants(output, OutputFormat::kJson)) {
    write_file_atomically((dir / "static.json").string(), json);
    written.push_back((dir / "static.json").string());
  }
  if (last_state != nullptr && wants(output, OutputFormat::kVtu)) {
    const VtuFields fields = resultant_fields(m.mesh, assembler, *m.element, m.law, *last_state);
    const VtuFormat format{output.vtu_encoding, output.mirror && m.symmetry_factor > 1};
    write_vtu((dir / "static.vtu").string(), m.mesh, *last_state, fields, format);
    written.push_back((dir / "static.vtu").string());
  }
  err << "wrote ";
  for (std::size_t i = 0; i < written.size(); ++i)
    err << (i == 0 ? "" : i + 1 == written.size() ? " and " : ", ") << written[i];
  err << (written.empty() ? "nothing (output.formats)" : "") << "\n";
}

// One VTU per stability change (static_stability_NN.vtu: the state at the event, its resultants
// and the critical mode as the point field `critical_mode`); returns the files' names.
std::vector<std::string> write_stability_vtus(const std::filesystem::path& dir, const ShellModel& m,
                                              const Assembler& assembler,
                                              const std::vector<StaticEvent>& events) {
  std::vector<std::string> names;
  for (const StaticEvent& e : events) {
    if (e.type != cont::EventType::kStabilityChange || e.states.empty()) continue;
    char name[40];
    std::snprintf(name, sizeof name, "static_stability_%02d.vtu",
                  static_cast<int>(names.size()) + 1);
    VtuFields fields = resultant_fields(m.mesh, assembler, *m.element, m.law, e.states);
    fields.point_data["critical_mode"] = e.mode;
    write_vtu((dir / name).string(), m.mesh, e.states, fields);
    names.push_back(name);
  }
  return names;
}

std::string case_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool on_nominal_grid(double load_factor, int steps) {
  const double k = load_factor * steps;
  return std::abs(k - std::round(k)) < 1e-9 * steps;
}

}  // namespace

int run_static_command(const StaticCommandOptions& o, std::ostream& out, std::ostream& err) {
  check_thread_count(o.threads);
  const CaseFile c = read_case_file(o.case_file);
  const std::string text = case_text(o.case_file);
  if (!c.load)
    throw_input("a static run needs a `load` section, e.g. load: {type: apex_force, force: 1 kN}",
                Where{c.file, "load", "", 0});
  const ShellModel m = [&] {
    try {
      return build_shell_model(c);
    } catch (const Error& e) {
      throw located_in_case(e, text);
    }
  }();
  for (const auto& w : m.warnings) err << "shellindent: warning: " << w << "\n";
  StaticSettings settings = c.static_run;
  settings.steps = c.load->steps;
  settings.record_nodes = {m.apex_node()};
  const RecordedSets sets = record_sets(c, m.mesh, text, settings);  // an unknown set: exit 2
  // The output directory is made (and checked, and locked) once the input is valid and before
  // the run, so that a long run cannot be lost to a bad --out at the end.
  const std::filesystem::path dir = o.out_dir.empty() ? c.output.dir : o.out_dir;
  const Where dir_where =
      o.out_dir.empty()
          ? located_in_case(Error(ErrorKind::kInput, "", {c.file, "output.dir", dir.string(), 0}),
                            text)
                .where()
          : Where{"command line", "--out", dir.string(), 0};
  prepare_output_directory(dir, dir_where);
  const OutputLock lock(dir, dir_where);

  const DofMap dofs = make_dof_map(m.mesh, m.supports, m.displacements);
  const bool natural = settings.method == PathMethod::kNatural;
  if (settings.stability && m.symmetry_factor > 1)
    err << "note: static.stability on a symmetric part of the shell sees only the modes symmetric "
           "about its planes (mesh.symmetry: full for all of them)\n";
  err << "static: " << m.mesh.num_nodes() << " nodes, " << m.mesh.num_elements() << " "
      << m.element->name() << " elements, " << dofs.num_free() << " free dofs, "
      << (natural ? std::to_string(settings.steps) + " load steps"
                  : "pseudo-arclength to load factor " + std::to_string(settings.load_factor_max))
      << "\n";

  std::vector<StaticRow> rows;
  std::vector<NodeState> last_state;
  // Ctrl-C / SIGTERM stop the run after the step under way; every converged step is written.
  const InterruptGuard guard;
  const auto on_step = [&](const StepResult& r, const std::vector<NodeState>& s) {
    rows.push_back(make_row(r, m.symmetry_factor, sets));
    last_state = s;
    const StaticRow& row = rows.back();
    err << "step " << rows.size() << ": load factor " << r.load_factor << ", " << r.iterations
        << " iterations, apex deflection " << row.deflection << " mm"
        << (!natural || on_nominal_grid(r.load_factor, settings.steps)
                ? ""
                : " (step cut back after a failed attempt)")
        << "\n";
    // Reactions must balance the load; an element that cannot represent rigid-body motion
    // (bernstein4) or a too-loose tolerance shows here first. Without a force along z (e.g. an
    // end moment alone) there is no scale to compare the reactions' round-off with: no check.
    if (row.force != 0 && std::abs(row.reaction - row.force) > 1e-6 * std::abs(row.force))
      err << "shellindent: warning: reactions " << row.reaction << " N do not balance the applied "
          << row.force << " N: the results are not in equilibrium\n";
    return !interrupted();
  };
  StaticResult result;
  try {
    result = run_static(m.mesh, dofs, *m.element, m.law, m.kinematics, m.loads, settings, on_step,
                        o.threads);
  } catch (const Error& e) {
    // Input errors raised inside the run come from the elements (a degenerate element).
    if (e.kind() != ErrorKind::kInput) throw;
    Where w = e.where();
    if (w.key == "element") w.key.clear();  // a degenerate element (shell/quad4_shell.cpp)
    throw located_in_case(
        Error(e.kind(), e.reason(), w).within(Where{c.file, "mesh.element", m.element->name(), 0}),
        text);
  }
  // The run's callback is how a signal stops it: say so in the user's terms.
  const std::string failure = interrupted() && result.failure.empty()
                                  ? std::string("interrupted (") + interrupt_name() + ")"
                                  : result.failure;
  std::vector<StaticEventRow> events;
  for (const StaticEvent& e : result.events)
    events.push_back({e.type, make_row(e.at, m.symmetry_factor, sets), e.criticality,
                      e.negative_before, e.negative_after});

  out << "Static run of " << c.file << " (whole-shell values; force and apex deflection along -z)\n"
      << "  lambda        force_N  deflection_mm  strain_energy_Nmm     reaction_N  iters\n";
  for (const auto& r : rows) out << format_row(r) << "\n";
  for (const auto& e : events)
    out << "  " << cont::event_type_name(e.type)
        << (e.type == cont::EventType::kStabilityChange
                ? " (" + cont::criticality_name(e.criticality) + ", " +
                      std::to_string(e.negative_before) + " -> " +
                      std::to_string(e.negative_after) + " negative eigenvalues)"
                : std::string())
        << " at load factor " << e.row.load_factor << ": force " << e.row.force
        << " N, apex deflection " << e.row.deflection << " mm\n";

  const Assembler assembler(m.mesh, dofs, *m.element, m.law, m.kinematics, o.threads);
  write_results(dir, m, c.output, assembler, rows.empty() ? nullptr : &last_state,
                csv_text(rows, sets, settings.stability),
                json_of(c, m, dofs, rows, events, sets, failure).dump(2) + "\n", err);
  if (wants(c.output, OutputFormat::kVtu)) {
    const std::vector<std::string> modes = write_stability_vtus(dir, m, assembler, result.events);
    if (!modes.empty())
      err << "wrote " << modes.size() << " stability VTU file(s) (critical_mode) in "
          << dir.string() << "\n";
  }
  if (failure.empty()) return 0;
  err << "shellindent: error: the run stopped after " << rows.size() << " converged step(s)"
      << (rows.empty() ? "" : " at load factor " + std::to_string(rows.back().load_factor)) << ": "
      << failure << "\n";
  return 1;
}

}  // namespace si
