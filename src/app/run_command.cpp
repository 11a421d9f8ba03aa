#include "app/run_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "analysis/companion_mesh.hpp"
#include "analysis/indentation_run.hpp"
#include "analysis/mode_field.hpp"
#include "app/interrupt_signals.hpp"
#include "app/path_vtus.hpp"
#include "app/progress_line.hpp"
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
#include "io/spellings.hpp"
#include "io/thread_count.hpp"

namespace si {
namespace {

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
                                          const PathVtus& vtus, const std::string& damage_rows) {
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
    write_file_atomically((dir / "path.pvd").string(), vtus.pvd());
    written.push_back("path.pvd and " + std::to_string(vtus.size()) + " VTU files");
  }
  return written;
}

// What a run with a `damage:` section found, in words beside the table: each onset with its
// mode and place, the Davies-Zhang threshold and, per impact energy, the depth and force where
// the indenter's work reaches it, or that the path's work never does (an energy beyond the path
// is reported, never extrapolated: docs/theory/failure.md 5).
void print_damage_summary(const PathResult& r, std::ostream& out) {
  for (const DamageOnset& o : r.damage.onsets) {
    out << "damage onset: " << spelling(criterion_spellings(), o.criterion) << " ("
        << spelling(failure_mode_spellings(), o.at.mode) << ", "
        << (o.at.interface ? "interface " + std::to_string(o.at.ply) + "/" +
                                 std::to_string(o.at.ply + 1)
                           : "ply " + std::to_string(o.at.ply + 1) + " " +
                                 spelling(ply_position_spellings(), o.at.position))
        << ") at depth " << format_quantity(o.depth, Dimension::kLength) << ", force "
        << format_quantity(o.force, Dimension::kForce) << ", work "
        << format_quantity(o.work, Dimension::kEnergy) << "\n";
  }
  if (r.damage.threshold)
    out << "Davies-Zhang delamination threshold: "
        << format_quantity(r.damage.threshold->load, Dimension::kForce)
        << (std::isnan(r.damage.threshold_depth)
                ? " (not reached on the path)"
                : ", reached at depth " +
                      format_quantity(r.damage.threshold_depth, Dimension::kLength))
        << "\n";
  for (const EnergyPoint& e : r.damage.energies) {
    out << "impact energy " << format_quantity(e.energy, Dimension::kEnergy) << ": ";
    if (e.outcome == EnergyOutcome::kReached)
      out << "depth " << format_quantity(e.depth, Dimension::kLength) << ", force "
          << format_quantity(e.force, Dimension::kForce) << "\n";
    else
      out << "beyond the path (its largest work is "
          << format_quantity(e.max_work, Dimension::kEnergy)
          << "); not extrapolated: run deeper (path.depth_max) to reach it\n";
  }
}

std::string percent(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g %%", 100 * v);
  return text;
}

// The run's discretisation error in words (docs/theory/discretisation-error.md): the largest
// estimate over the path and the last one, of the energy norm and, with a companion run, of the
// force; a warning on `err` when the force's (else the energy norm's) exceeds mesh.tolerance.
void print_error_summary(const PathResult& r, double tolerance, std::ostream& out,
                         std::ostream& err) {
  const PathPoint* worst = nullptr;
  for (const PathPoint& p : r.points)
    if (!worst || p.state.error_estimate > worst->state.error_estimate) worst = &p;
  if (!worst || !(worst->state.error_estimate > 0)) return;
  out << "discretisation error (Zienkiewicz-Zhu, energy norm): max "
      << percent(worst->state.error_estimate) << " at depth "
      << format_quantity(worst->state.depth, Dimension::kLength) << ", "
      << percent(r.points.back().state.error_estimate) << " at the last point\n";
  double estimate = worst->state.error_estimate;
  if (const PathPoint* force = largest_force_error(r)) {
    worst = force;
    estimate = force->force_error;
    out << "force discretisation error (companion run, element sizes x2): max " << percent(estimate)
        << " at depth " << format_quantity(force->state.depth, Dimension::kLength) << "\n";
  }
  if (tolerance > 0 && estimate > tolerance)
    err << "shellindent: warning: mesh.tolerance = " << percent(tolerance)
        << " exceeded (estimated " << percent(estimate) << " at depth "
        << format_quantity(worst->state.depth, Dimension::kLength) << "): refine mesh.size_apex\n";
}

// mesh.error_estimate: companion - the case again on the mesh with twice the element sizes, at
// the run's depths, for every point's force_error (analysis/companion_mesh.hpp), with its own
// progress lines; what it could not do is said, and the run's own results stand. `run` is the
// run's own case as its set-up resolved it (the refined zone the companion must share).
void add_force_errors(const IndentationCase& run, int threads, PathResult& r, std::ostream& err) {
  if (run.mesh.error_estimate != ErrorEstimate::kCompanion || interrupted()) return;
  std::optional<ProgressLine> progress;
  const CompanionRun c = run_companion(
      run, r, threads,
      [&](const CompanionRun& built) {
        err << "companion run for the force's discretisation error (element sizes x2): "
            << built.shell_unknowns << " shell unknowns\n";
        progress.emplace(err, built.depth_max);
      },
      [&](const PathPoint& p, const cont::Vector&) {
        progress->show(p);
        return !interrupted();
      });
  if (progress) progress->done();
  if (!c.why_not.empty())
    err << "shellindent: warning: no force error estimate (companion run, element sizes x2): "
        << c.why_not << "\n";
  else if (!c.path.completed)
    err << "shellindent: warning: the companion run stopped"
        << (c.path.points.empty() ? std::string()
                                  : " at depth " + format_quantity(c.path.points.back().state.depth,
                                                                   Dimension::kLength))
        << " (" << (interrupted() ? "interrupted" : c.path.reason)
        << "): the points beyond it have no force_error_estimate\n";
}

// Where `--resume` would go on from: a stopped run keeps its last periodic checkpoint (so that a
// resume repeats the uninterrupted run bit for bit), which may lie several points back, or be
// the start's only.
void print_resume_point(const PathResult& r, int interval, std::ostream& err) {
  const std::size_t held = r.checkpointed_points;
  if (held == 0 || held > r.points.size()) return;
  err << "run: --resume continues from depth "
      << format_quantity(r.points[held - 1].state.depth, Dimension::kLength);
  if (held < r.points.size())
    err << ", point " << held << " of " << r.points.size() << " (a checkpoint is kept every "
        << interval << " points; the " << r.points.size() - held << " after it are solved again)";
  err << "\n";
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
      << setup.problem->candidates().size() << " contact candidates; the indenter touches after "
      << setup.problem->first_touch() << " mm of travel from indenter.position, where depth 0 is\n";
  if (!cf.mesh.refine_radius && setup.spec.mesh.refine_radius) {
    char zone[32];
    std::snprintf(zone, sizeof zone, "%.3g", *setup.spec.mesh.refine_radius);
    err << "mesh: refined to size_apex within " << zone
        << " mm of the apex, where the indenter at depth_max would cut the undeformed face "
           "(mesh.refine_radius sets it)\n";
  }
  if (setup.imperfection) err << imperfection_summary(*setup.imperfection) << "\n";
  if (cf.path.stability && setup.model.symmetry_factor > 1)
    err << "note: path.stability on a symmetric part of the shell sees only the modes symmetric "
           "about its planes (mesh.symmetry: full for all of them)\n";

  const OutputChoice formats = output_choice(cf.output);
  const CaseDigest digest = case_digest(text);
  ProgressLine progress(err, cf.path.depth_max);
  PathVtus vtus(dir, cf.output, setup, formats.vtu);
  std::string damage_rows;  // damage_points.csv's rows so far (saved with the checkpoints)
  InterruptGuard guard;
  const PathCallback on_point = [&](const PathPoint& p, const cont::Vector& z) {
    progress.show(p);
    if (formats.csv) damage_rows += damage_points_rows(setup, p, z);
    vtus.at_point(setup, p, z);
    return !interrupted();
  };
  control.save_record = [&] {
    nlohmann::json record{{"case", digest.to_json()}, {"vtu", vtus.record()}};
    if (setup.damage) record["damage_points"] = damage_rows;
    return record;
  };
  control.restore_record = [&](const nlohmann::json& record) {
    check_same_case(record, digest, cf.file, text, control.checkpoint);
    vtus.restore(record.value("vtu", nlohmann::json::array()));
    damage_rows = record.value("damage_points", std::string());
  };
  control.on_step_failure = [&](const cont::StepFailure& f) { progress.failed(f); };
  PathResult r = run_indentation_path(setup, on_point, control);
  progress.done();
  // The path's files say why it stopped in the user's terms (the callback is how a signal
  // stops a continuation; "stopped by the callback" tells a user nothing).
  if (r.status == RunStatus::kStopped && interrupted())
    r.reason = std::string("interrupted (") + interrupt_name() + ")";
  const int event_files = vtus.after_run(setup, r);
  add_force_errors(setup.spec, o.threads, r, err);

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
  print_damage_summary(r, out);
  print_error_summary(r, cf.mesh.tolerance, out, err);
  for (const std::string& line : critical_points_summary(r.critical)) out << line << "\n";

  std::vector<std::string> written = write_path_files(dir, formats, setup, r, vtus, damage_rows);
  if (event_files > 0)
    written.push_back(std::to_string(event_files) + " of them at located events (event_NN.vtu)");
  // Why a completed path ended, said where the user looks: it may carry a second statement
  // (path.branch_switch without a bifurcation on the path).
  if (r.completed) err << "run: " << r.reason << "\n";
  err << "wrote ";
  for (std::size_t i = 0; i < written.size(); ++i) err << (i ? ", " : "") << written[i];
  err << (written.empty() ? "nothing (output.formats)" : "") << "\n";
  if (r.completed) return 0;
  err << "shellindent: error: the run stopped after " << r.points.size() << " converged point(s)"
      << (r.points.empty()
              ? ""
              : " at depth " + format_quantity(r.points.back().state.depth, Dimension::kLength))
      << ": " << r.reason << "\n";
  print_resume_point(r, control.checkpoint_interval, err);
  return 1;
}

}  // namespace si
