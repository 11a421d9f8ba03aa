#include "app/run_command.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "analysis/indentation_run.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/case_file.hpp"
#include "io/output_directory.hpp"
#include "io/path_results.hpp"
#include "io/result_fields.hpp"
#include "io/spellings.hpp"
#include "io/vtu_writer.hpp"

namespace si {
namespace {

// Ctrl-C asks the run to stop after the current point. A signal handler can only reach static
// storage, so this one flag is the exception to "no global state"; it lives in this file only.
std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) {
  g_interrupted = true;
}

class InterruptGuard {
 public:
  InterruptGuard() { previous_ = std::signal(SIGINT, on_interrupt); }
  ~InterruptGuard() { std::signal(SIGINT, previous_); }

 private:
  void (*previous_)(int) = nullptr;
};

// The VTU of one point: resultants plus the contact pressure and force at every node.
void write_point_vtu(const std::filesystem::path& file, const IndentationSetup& s,
                     const IndentationState& st, const cont::Vector& z) {
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
  write_vtu(file.string(), s.model.mesh, state, fields);
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

}  // namespace

std::string default_case_yaml() {
  return "# Built-in default of `shellindent run`: the source paper's cap (docs/case-file.md).\n"
         "material: paper-carbon-epoxy\n"
         "laminate: {layup: \"[0/0]2S\", ply_thickness: 0.475 mm, reference: mid}\n"
         "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
         "mesh: {element: mitc4, size_apex: 0.5 mm, size_edge: 2 mm, refine_radius: 13 mm,\n"
         "       symmetry: quarter}\n"
         "kinematics: nonlinear\n"
         "indenter: {shape: sphere, radius: 12.7 mm}\n"
         "contact: {surface: outer, solver: kinsol}\n"
         "path: {method: pseudo_arclength, depth_max: 10 mm, step: 0.1 mm}\n"
         "output: {dir: results/paper_cap/, vtu_every: 10}\n";
}

int run_run_command(const RunCommandOptions& o, std::ostream& out, std::ostream& err) {
  const CaseFile cf = o.case_file.empty()
                          ? parse_case_file(default_case_yaml(), "built-in default case")
                          : read_case_file(o.case_file);
  IndentationSetup setup(cf, o.threads);
  for (const auto& w : setup.model.warnings) err << "shellindent: warning: " << w << "\n";
  const std::filesystem::path dir = o.out_dir.empty() ? cf.output.dir : o.out_dir;
  prepare_output_directory(dir, o.out_dir.empty()
                                    ? Where{cf.file, "output.dir", dir.string(), 0}
                                    : Where{"command line", "--out", dir.string(), 0});
  err << "run: " << cf.file << ": " << setup.model.mesh.num_nodes() << " nodes, "
      << setup.model.mesh.num_elements() << " " << setup.model.element->name() << " elements, "
      << setup.problem->num_shell_unknowns() << " shell unknowns, "
      << setup.problem->candidates().size() << " contact candidates, first touch at travel "
      << setup.problem->first_touch() << " mm\n";

  Progress progress(err, cf.path.depth_max);
  std::vector<std::pair<double, std::string>> vtus;
  g_interrupted = false;
  InterruptGuard guard;
  const PathCallback on_point = [&](const PathPoint& p, const cont::Vector& z) {
    progress.show(p);
    const int every = cf.output.vtu_every;
    if (every > 0 && p.index % every == 0) {
      char name[32];
      std::snprintf(name, sizeof name, "path_%04d.vtu", p.index);
      write_point_vtu(dir / name, setup, p.state, z);
      vtus.emplace_back(p.state.depth, name);
    }
    return !g_interrupted;
  };
  PathControl control;
  control.checkpoint = (dir / "checkpoint.json").string();
  control.resume = o.resume;
  if (o.resume && !std::filesystem::exists(control.checkpoint))
    throw_input("nothing to resume: no checkpoint in the output directory",
                Where{"command line", "--resume", control.checkpoint, 0});
  const PathResult r = run_indentation_path(setup, on_point, control);
  progress.done();

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
          << (e.against.empty() ? "" : " against " + e.against) << " at depth " << e.p << " mm\n";

  write_file_atomically((dir / "path.csv").string(), path_csv(r));
  write_file_atomically((dir / "path.json").string(), path_json(setup, r).dump(2) + "\n");
  write_file_atomically((dir / "events.json").string(), events_json(r).dump(2) + "\n");
  const bool arclength = r.method == RunMethod::kPseudoArclength;
  if (arclength)
    write_file_atomically((dir / "path_grid.csv").string(),
                          path_grid_csv(r, cf.path.step, cf.path.depth_max));
  if (!vtus.empty()) write_file_atomically((dir / "path.pvd").string(), pvd_text(vtus));
  err << "wrote " << (dir / "path.csv").string() << ", path.json, events.json"
      << (arclength ? ", path_grid.csv (interpolated at the depth steps)" : "")
      << (vtus.empty() ? "" : ", path.pvd and " + std::to_string(vtus.size()) + " VTU files")
      << "\n";
  if (r.completed) return 0;
  err << "shellindent: error: the run stopped after " << r.points.size() << " converged point(s)"
      << (r.points.empty() ? ""
                           : " at depth " + std::to_string(r.points.back().state.depth) + " mm")
      << ": "
      << (r.status == RunStatus::kStopped && g_interrupted ? "interrupted (Ctrl-C)" : r.reason)
      << "\n";
  return 1;
}

}  // namespace si
