#include "app/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "analysis/indentation_run.hpp"
#include "app/interrupt_signals.hpp"
#include "app/thread_count.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "io/case_digest.hpp"
#include "io/case_file.hpp"
#include "io/case_key_location.hpp"
#include "io/critical_points_json.hpp"
#include "io/damage_fields.hpp"
#include "io/default_case.hpp"
#include "io/output_directory.hpp"
#include "io/output_lock.hpp"
#include "io/path_results.hpp"
#include "io/result_fields.hpp"
#include "io/spellings.hpp"
#include "io/vtu_writer.hpp"

namespace si {
namespace {

// The VTU of one point: resultants plus the contact pressure and force at every node, and any
// `extra` fields.
void write_point_vtu(const std::filesystem::path& file, const IndentationSetup& s,
                     const IndentationState& st, const cont::Vector& z,
                     const VtuFields& extra = {}) {
  const IndentationProblem& p = *s.problem;
  const std::vector<NodeState> state = p.node_states(z);
  VtuFields fields =
      resultant_fields(s.model.mesh, p.assembler(), *s.model.element, s.model.law, state);
  Eigen::VectorXd pressure = Eigen::VectorXd::Zero(s.model.mesh.num_nodes());
  Eigen::VectorXd force = pressure;
  for (std::size_t i = 0; i < st.nodes.size(); ++i) {
    pressure[st.nodes[i]] = st.pressures[i];
    force[st.nodes[i]] = st.multipliers[i];
  }
  fields.point_data["contact_pressure"] = pressure;
  fields.point_data["contact_force"] = force;
  add_damage_fields(s, st, z, fields);
  for (const auto& [name, values] : extra.point_data) fields.point_data[name] = values;
  write_vtu(file.string(), s.model.mesh, state, fields);
}

// A stability event's mode as a nodal field: the translations of the mode (its shell part, chart
// coordinates), scaled so that the largest is 1 (a shape; its sign is Lanczos').
Eigen::MatrixXd mode_translations(const IndentationProblem& p, const cont::Vector& mode,
                                  int nodes) {
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(nodes, 3);
  for (int n = 0; n < nodes; ++n)
    for (int l = 0; l < 3; ++l) {
      const int eq = p.dofs().equation(DofMap::dof(n, l));
      if (eq >= 0 && eq < mode.size()) u(n, l) = mode[eq];
    }
  const double largest = u.cwiseAbs().maxCoeff();
  return largest > 0 ? Eigen::MatrixXd(u / largest) : u;
}

// One VTU per stability change (stability_NN.vtu, at the event's point, with its critical mode
// as the point field `critical_mode`); returns the files' names. The problem may have grown its
// candidate set since the event: the appended multipliers are zero at the event.
std::vector<std::string> write_stability_vtus(const std::filesystem::path& dir, IndentationSetup& s,
                                              const PathResult& r) {
  std::vector<std::string> names;
  IndentationProblem& p = *s.problem;
  for (const cont::Event& e : r.events) {
    if (e.type != cont::EventType::kStabilityChange || e.x.size() == 0 || e.x.size() > p.size())
      continue;
    cont::Vector z = cont::Vector::Zero(p.size());
    z.head(e.x.size()) = e.x;
    char name[32];
    std::snprintf(name, sizeof name, "stability_%02d.vtu", static_cast<int>(names.size()) + 1);
    VtuFields extra;
    extra.point_data["critical_mode"] = mode_translations(p, e.mode, s.model.mesh.num_nodes());
    write_point_vtu(dir / name, s, p.evaluate(z, e.p), z, extra);
    names.push_back(name);
  }
  return names;
}

std::string pvd_text(const std::vector<std::pair<double, std::string>>& files) {
  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [depth, name] : files)
    os << "  <DataSet timestep=\"" << depth << "\" file=\"" << name << "\"/>\n";
  os << "</Collection>\n</VTKFile>\n";
  return os.str();
}

// The force-depth table on stdout; with a local contact law (contact.local) the local
// indentation (path.csv's local_indent_mm) follows the apex deflection, the two parts of the
// travel.
std::string table_header(bool local) {
  return std::string("depth_mm      force_N  apex_w_mm") + (local ? "  local_mm" : "") +
         " radius_mm   energy_Nmm     work_Nmm iters";
}

std::string table_row(const PathPoint& p, bool local) {
  char line[200], part[32] = "";
  const IndentationState& s = p.state;
  if (local) std::snprintf(part, sizeof part, " %9.5f", s.local_indentation);
  std::snprintf(line, sizeof line, "%8.4f %12.6g %10.5f%s %9.4f %12.6g %12.6g %5d", s.depth,
                s.force, s.apex_deflection, part, s.contact_radius, s.energy, p.work, p.iterations);
  return line;
}

// One progress line per point; on a terminal it overwrites itself.
class Progress {
 public:
  Progress(std::ostream& err, double depth_max) : err_(err), depth_max_(depth_max) {}
  void show(const PathPoint& p) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double d = p.state.depth;
    char eta[32] = "";
    if (d > 0 && d < depth_max_)
      std::snprintf(eta, sizeof eta, ", ETA %.0f s", elapsed * (depth_max_ - d) / d);
    char line[256];
    std::snprintf(line, sizeof line,
                  "depth %.4f / %.4g mm, force %.6g N, %d nodes in contact, step %.3g, %d "
                  "iterations, %.1f s%s",
                  d, depth_max_, p.state.force, p.state.contact_nodes, p.step, p.iterations,
                  elapsed, eta);
    if (tty_)
      err_ << '\r' << line << "\033[K" << std::flush;
    else
      err_ << line << '\n';
  }
  void done() {
    if (tty_) err_ << '\n';
  }

 private:
  std::ostream& err_;
  double depth_max_;
  bool tty_ = isatty(STDERR_FILENO) != 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string vtu_name(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "path_%04d.vtu", index);
  return name;
}

std::string case_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// output.formats: which result files are written (checkpoint.json always, for --resume).
struct OutputChoice {
  bool csv = false, json = false, vtu = false;
};

OutputChoice output_choice(const OutputSpec& output) {
  OutputChoice c;
  for (OutputFormat f : output.formats) {
    c.csv = c.csv || f == OutputFormat::kCsv;
    c.json = c.json || f == OutputFormat::kJson;
    c.vtu = c.vtu || f == OutputFormat::kVtu;
  }
  return c;
}

// Refuses a resume with another case than the one that wrote the checkpoint (io/case_digest.hpp),
// naming the case file's first key that differs and its line.
void check_same_case(const nlohmann::json& record, const CaseDigest& now, const std::string& file,
                     const std::string& text, const std::string& checkpoint) {
  CaseDigest before;
  try {
    before = CaseDigest::from_json(record.at("case"));
  } catch (const std::exception&) {
    throw_input("cannot resume: the checkpoint does not say which case wrote it",
                Where{checkpoint, "", "", 0});
  }
  std::string key;
  const std::vector<std::string> differences = case_differences(now, before, key);
  if (differences.empty()) return;
  std::string list;
  for (const std::string& d : differences) list += (list.empty() ? "" : "; ") + d;
  const Where where{file, key, "", 0};
  throw located_in_case(
      Error(ErrorKind::kInput,
            "cannot resume: " + checkpoint + " was written for another case (" + list +
                "); resume with that case, or run without --resume to start over",
            where),
      text);
}

// The result files of output.formats (docs/results.md); returns what was written, for the
// "wrote ..." line.
std::vector<std::string> write_path_files(const std::filesystem::path& dir,
                                          const OutputChoice& formats,
                                          const IndentationSetup& setup, const PathResult& r,
                                          const std::vector<std::pair<double, std::string>>& vtus,
                                          const std::string& damage_rows) {
  const PathSpec& path = setup.spec.path;
  std::vector<std::string> written;
  const bool arclength = r.method == RunMethod::kPseudoArclength;
  if (formats.csv) {
    write_file_atomically((dir / "path.csv").string(), path_csv(r));
    written.push_back((dir / "path.csv").string());
    if (arclength) {
      write_file_atomically((dir / "path_grid.csv").string(),
                            path_grid_csv(r, path.step, path.depth_max));
      written.push_back("path_grid.csv (interpolated at the depth steps)");
    }
    if (setup.damage) {
      write_file_atomically((dir / "damage_points.csv").string(),
                            damage_points_header(setup) + damage_rows);
      written.push_back("damage_points.csv");
    }
  }
  if (formats.json) {
    write_file_atomically((dir / "path.json").string(), path_json(setup, r).dump(2) + "\n");
    write_file_atomically((dir / "events.json").string(), events_json(r).dump(2) + "\n");
    written.push_back((written.empty() ? (dir / "path.json").string() : "path.json") +
                      ", events.json");
  }
  if (!vtus.empty()) {
    write_file_atomically((dir / "path.pvd").string(), pvd_text(vtus));
    written.push_back("path.pvd and " + std::to_string(vtus.size()) + " VTU files");
  }
  return written;
}

}  // namespace

int run_run_command(const RunCommandOptions& o, std::ostream& out, std::ostream& err) {
  check_thread_count(o.threads);
  const std::string text = o.case_file.empty() ? default_case_yaml() : case_text(o.case_file);
  const CaseFile cf =
      o.case_file.empty() ? parse_case_file(text, kDefaultCaseLabel) : read_case_file(o.case_file);
  std::optional<IndentationSetup> built;
  try {
    built.emplace(cf, o.threads);
  } catch (const Error& e) {
    throw located_in_case(e, text);
  }
  IndentationSetup& setup = *built;
  for (const auto& w : setup.model.warnings) err << "shellindent: warning: " << w << "\n";
  const std::filesystem::path dir = o.out_dir.empty() ? cf.output.dir : o.out_dir;
  const Where dir_where =
      o.out_dir.empty()
          ? located_in_case(Error(ErrorKind::kInput, "", {cf.file, "output.dir", dir.string(), 0}),
                            text)
                .where()
          : Where{"command line", "--out", dir.string(), 0};
  PathControl control;
  control.checkpoint = (dir / "checkpoint.json").string();
  control.resume = o.resume;
  // Before anything is made: a mistaken --resume must not leave an empty directory behind.
  if (o.resume && !std::filesystem::exists(control.checkpoint))
    throw_input("nothing to resume: no checkpoint in the output directory",
                Where{"command line", "--resume", control.checkpoint, 0});
  prepare_output_directory(dir, dir_where);
  const OutputLock lock(dir, dir_where);
  err << "run: " << cf.file << ": " << setup.model.mesh.num_nodes() << " nodes, "
      << setup.model.mesh.num_elements() << " " << setup.model.element->name() << " elements, "
      << setup.problem->num_shell_unknowns() << " shell unknowns, "
      << setup.problem->candidates().size() << " contact candidates, first touch at travel "
      << setup.problem->first_touch() << " mm\n";
  if (cf.path.stability && setup.model.symmetry_factor > 1)
    err << "note: path.stability on a symmetric part of the shell sees only the modes symmetric "
           "about its planes (mesh.symmetry: full for all of them)\n";

  const OutputChoice formats = output_choice(cf.output);
  const CaseDigest digest = case_digest(text);
  Progress progress(err, cf.path.depth_max);
  std::vector<std::pair<double, std::string>> vtus;
  std::string damage_rows;  // damage_points.csv's rows so far (saved with the checkpoints)
  InterruptGuard guard;
  const PathCallback on_point = [&](const PathPoint& p, const cont::Vector& z) {
    progress.show(p);
    if (formats.csv) damage_rows += damage_points_rows(setup, p, z);
    const int every = cf.output.vtu_every;
    if (formats.vtu && every > 0 && p.index % every == 0) {
      write_point_vtu(dir / vtu_name(p.index), setup, p.state, z);
      vtus.emplace_back(p.state.depth, vtu_name(p.index));
    }
    return !interrupted();
  };
  control.save_record = [&] {
    nlohmann::json frames = nlohmann::json::array();
    for (const auto& [depth, name] : vtus) frames.push_back({depth, name});
    nlohmann::json record{{"case", digest.to_json()}, {"vtu", frames}};
    if (setup.damage) record["damage_points"] = damage_rows;
    return record;
  };
  control.restore_record = [&](const nlohmann::json& record) {
    check_same_case(record, digest, cf.file, text, control.checkpoint);
    vtus.clear();
    for (const auto& f : record.value("vtu", nlohmann::json::array()))
      vtus.emplace_back(f.at(0).get<double>(), f.at(1).get<std::string>());
    damage_rows = record.value("damage_points", std::string());
  };
  PathResult r = run_indentation_path(setup, on_point, control);
  progress.done();
  // The path's files say why it stopped in the user's terms (the callback is how a signal
  // stops a continuation; "stopped by the callback" tells a user nothing).
  if (r.status == RunStatus::kStopped && interrupted())
    r.reason = std::string("interrupted (") + interrupt_name() + ")";
  // The last point always has its fields (vtu_every counts points: a 0-10 mm run's last VTU was
  // at 6.22 mm).
  if (formats.vtu && cf.output.vtu_every > 0 && !r.points.empty() &&
      r.final_unknowns.size() == setup.problem->size()) {
    const PathPoint& last = r.points.back();
    const std::string name = vtu_name(last.index);
    if (vtus.empty() || vtus.back().second != name) {
      write_point_vtu(dir / name, setup,
                      setup.problem->evaluate(r.final_unknowns, last.state.depth),
                      r.final_unknowns);
      vtus.emplace_back(last.state.depth, name);
    }
  }

  const bool local = setup.problem->local_law().kind != LocalLawKind::kNone;
  out << "Indentation of " << cf.file << " (" << run_method_name(r.method)
      << "; whole-shell values, depth = indenter travel after first touch"
      << (local ? ", local law " + spelling(local_contact_spellings(), cf.contact.local) : "")
      << ")\n"
      << table_header(local) << "\n";
  for (const PathPoint& p : r.points) out << table_row(p, local) << "\n";
  for (const cont::Event& e : r.events)
    if (e.type != cont::EventType::kSignatureChange)
      out << "event: " << e.name << (e.monitor.empty() ? "" : " of " + e.monitor)
          << (e.against.empty() ? "" : " against " + e.against)
          << (e.type == cont::EventType::kStabilityChange
                  ? " (" + cont::criticality_name(e.criticality) + ")"
                  : "")
          << " at depth " << e.p << " mm\n";
  for (const std::string& line : critical_points_summary(r.critical)) out << line << "\n";

  std::vector<std::string> written = write_path_files(dir, formats, setup, r, vtus, damage_rows);
  if (formats.vtu) {
    const std::vector<std::string> modes = write_stability_vtus(dir, setup, r);
    if (!modes.empty())
      written.push_back(std::to_string(modes.size()) + " stability VTU file(s) (critical_mode)");
  }
  err << "wrote ";
  for (std::size_t i = 0; i < written.size(); ++i) err << (i ? ", " : "") << written[i];
  err << (written.empty() ? "nothing (output.formats)" : "") << "\n";
  if (r.completed) return 0;
  err << "shellindent: error: the run stopped after " << r.points.size() << " converged point(s)"
      << (r.points.empty()
              ? ""
              : " at depth " + format_quantity(r.points.back().state.depth, Dimension::kLength))
      << ": " << r.reason << "\n";
  return 1;
}

}  // namespace si
