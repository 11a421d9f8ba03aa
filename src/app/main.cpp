// The `shellindent` command line. CLI11 lives in this translation unit only (it compiles
// slowly); the commands themselves are plain functions in src/app/*_command.cpp.
//
// Exit codes: 0 success, 2 bad input (including bad options), 1 numerical failure, 3 internal.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "app/calibrate_command.hpp"
#include "app/fit_command.hpp"
#include "app/run_command.hpp"
#include "app/section_command.hpp"
#include "app/static_command.hpp"
#include "app/sweep_command.hpp"
#include "core/blas_threads.hpp"
#include "core/did_you_mean.hpp"
#include "core/error.hpp"

namespace {

constexpr const char* kDescription =
    "shellindent " SHELLINDENT_VERSION
    " - static indentation of laminated composite shells by rigid indenters.\n"
    "Section analysis (CLT, FSDT, variational-asymptotic Reissner-Mindlin law), static shell runs\n"
    "under apex force or pressure, and indentation paths (frictionless Lagrange-multiplier\n"
    "contact solved by KINSOL, natural or pseudo-arclength continuation in the depth).\n"
    "Quantities carry units: \"0.475 mm\", \"130 GPa\", \"45 deg\". Internal units: mm, N, MPa.";

constexpr const char* kSectionHelp =
    "Section properties of a laminate: CLT A, B, D; VAM A_R, transverse shear G (VAM fit, FSDT "
    "k = 5/6, equilibrium), load coupling F-bar and face compliance c_L.\n"
    "Examples:\n"
    "  shellindent section studies/paper_cap.yaml --json section.json\n"
    "  shellindent section --layup \"[45/-45]2S\" --material paper-carbon-epoxy "
    "--ply-thickness 0.475mm\n"
    "  shellindent section --paper --out results   (all of the source paper's lay-ups)";

constexpr const char* kStaticHelp =
    "Load-controlled static run of a shell without contact, from a case file with a `load` "
    "section (apex_force or pressure, in `steps` equal increments; linear or nonlinear from "
    "`kinematics`), or with `static: {method: pseudo_arclength}` through limit points (snap-"
    "through, snap-back; the limit points are located). Prints a progress line per step to "
    "stderr and a table (load factor, force N, "
    "apex deflection mm, strain energy N*mm, reaction N, iterations) to stdout, then writes "
    "static.csv, static.json and static.vtu (last step, nodal resultants N and M averaged over "
    "elements) to the output directory. With `static: {stability: true}` every step's stability "
    "(stable, lowest_eigenvalue) and the located stability changes (limit point or "
    "bifurcation, their mode in static_stability_NN.vtu). Exit 1 if a step fails (converged "
    "steps are written).\n"
    "Example:\n"
    "  shellindent static studies/cap_apex_load.yaml --out results/cap_apex_load";

constexpr const char* kRunHelp =
    "Indentation depth path of a case file: a rigid indenter pressed into the shell from first "
    "touch to path.depth_max (frictionless contact; KINSOL on the complementarity system with "
    "natural or pseudo-arclength continuation in the depth, or the linear fast path for "
    "kinematics: linear). Without a case file, runs the built-in default: the source paper's "
    "clamped carbon/epoxy cap, [0/0]2S, 12.7 mm sphere, 0 to 10 mm. Prints a progress line per "
    "converged point to stderr (depth, force, nodes in contact, step, Newton iterations, elapsed "
    "seconds and the time left at the pace of the last 8 steps) and the force-depth table to "
    "stdout (with contact.local, the local indentation beside the apex deflection); writes "
    "path.csv (columns "
    "depth_mm, force_N, reaction_N, apex_w_mm, contact radius and area, apex curvatures, energy, "
    "work, KKT residuals, iterations, step, local indentation and its energy (contact.local), "
    "the failure indices (damage), stable and lowest_eigenvalue (path.stability): "
    "docs/results.md), path.json, events.json and VTU files with "
    "the contact pressure (path.pvd for ParaView; damage_points.csv with `damage:`). Ctrl-C stops "
    "after the current point and "
    "writes what converged; continuation runs keep checkpoint.json and `--resume` continues "
    "from it. Exit 1 if the path stops early.\n"
    "Examples:\n"
    "  shellindent run                                   (the paper's cap, results/paper_cap/)\n"
    "  shellindent run studies/paper_cap.yaml --out results/cap_0_90";

constexpr const char* kSweepHelp =
    "Parameter study: every case of a study file (a base case file and the keys to vary, as "
    "product or zip) run as `shellindent run` would, each in DIR/cases/NNN_<values>/, at most -j "
    "at once as child processes. Finished cases are not run again, so a killed sweep resumes. "
    "Prints a line per finished case to stderr and the merged table to stdout; writes "
    "DIR/sweep.csv and sweep.json (per case: status, force at depth_max, force maximum, end "
    "energy, critical-force events, and with fit: C1, C2 of T = C1 h^C2 with 95% intervals). "
    "Exit 1 if a case failed. For a cluster: --emit DIR writes the cases and a task list for a "
    "SLURM job array or GNU parallel, --collect DIR merges their results; --scheduler runs the "
    "cases on a Dask cluster. See docs/sweeps.md.\n"
    "Examples:\n"
    "  shellindent sweep studies/paper_layups.yaml -j 2\n"
    "  shellindent sweep studies/paper_layups.yaml --quick --out /tmp/quick\n"
    "  shellindent sweep studies/paper_layups.yaml --emit /scratch/layups   (then: parallel -j 8 "
    "< /scratch/layups/tasks.txt; shellindent sweep --collect /scratch/layups)\n"
    "  shellindent sweep studies/paper_layups.yaml --scheduler tcp://head:8786";

constexpr const char* kFitHelp =
    "Fit a curve to two columns of a CSV file (header line required): y = C1 x^C2 fitted in linear "
    "space (power) or in log space (power-log), y = C x^1.5 (hertz), y = C1 x^C2 + C0 "
    "(power-offset), or a polynomial (poly, degree given or chosen by leave-one-out, AIC or AICc). "
    "Prints "
    "the parameters with standard errors and 95% intervals, R^2, Pearson r and RMSE, and writes "
    "them with the residuals as JSON (default DATA.fit-MODEL.json beside the CSV). A fit with as "
    "many parameters as points is flagged as interpolation. Exit 1 if the fit does not converge. "
    "See docs/fitting.md.\n"
    "Examples:\n"
    "  shellindent fit results/cap/static.csv --model power --x apex_deflection_mm --y force_N\n"
    "  shellindent fit c1.csv --model poly --x angle_deg --y C1 --degree auto\n"
    "  shellindent fit path.csv --model power-log --x depth_mm --y force_N --range 0.1:10";

constexpr const char* kCalibrateHelp =
    "Calibrate numbers of a case file against a measured force-travel curve: NLopt (LN_BOBYQA, "
    "derivative-free; or LD_SLSQP with finite differences) adjusts the chosen case-file keys "
    "(elastic constants of material, materials.NAME or indenter.material; "
    "laminate.ply_thickness) within their bounds to minimise the squared force misfit at the "
    "measured travels, each evaluation a full run of the case to the last measured travel. The "
    "CSV names its units in the header (travel_mm,force_N or \"travel (mm), force (kN)\"); "
    "travel is the indenter's travel after first touch. Prints a line per evaluation to stderr "
    "and the optimum with standard errors, 95% intervals, correlations and identifiability "
    "warnings to stdout; writes DIR/calibration.json, calibration_curve.csv and "
    "calibrated_case.yaml. Ctrl-C or SIGTERM stops and reports the best point so far. Exit 1 "
    "unless the "
    "search converged. See docs/calibration.md.\n"
    "Example:\n"
    "  shellindent calibrate cap.yaml --data test.csv --param material.E3=5:20GPa "
    "--param material.G13=1:6GPa:3GPa --out results/cal";

// "commands:" and one line per subcommand: its description up to the first '.', ':' or ','.
std::string command_list(const CLI::App& app) {
  std::string out = "commands:\n";
  for (const auto* sub : app.get_subcommands({})) {
    const std::string& text = sub->get_description();
    const std::string name = sub->get_name();
    out += "  " + name + std::string(name.size() < 11 ? 11 - name.size() : 1, ' ') +
           text.substr(0, text.find_first_of(".:,\n")) + "\n";
  }
  return out;
}

// CLI11 says "The following argument was not expected: --treads", and where the misspelt option
// is followed by its value, that this value is a case file that does not exist ("case: File does
// not exist: 2"): name the unknown option first, with the closest one of the command.
void refuse_unknown_options(const CLI::App& command, int argc, char** argv) {
  std::vector<std::string> known;
  for (const CLI::Option* option : command.get_options())
    for (const std::string& name : option->get_lnames()) known.push_back("--" + name);
  for (int i = 2; i < argc; ++i) {
    const std::string token = argv[i];
    if (token == "--") return;  // what follows are values
    if (token.size() < 3 || token.compare(0, 2, "--") != 0) continue;
    const std::string name = token.substr(0, token.find('='));
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw si::Error(si::ErrorKind::kInput,
                    "unknown option of '" + command.get_name() + "'" +
                        si::did_you_mean(name, known) + "; its options: " + list,
                    si::Where{"command line", "", name, 0});
  }
}

int run(int argc, char** argv) {
  CLI::App app{kDescription, "shellindent"};
  app.set_version_flag("--version", SHELLINDENT_VERSION);
  app.require_subcommand(1);
  app.footer("Run 'shellindent COMMAND --help' for the options of a command.");

  si::SectionCommandOptions so;
  auto* section = app.add_subcommand("section", kSectionHelp);
  section->add_option("case", so.case_file, "YAML case file (material and laminate are read)")
      ->check(CLI::ExistingFile);
  section->add_option("--layup", so.layup,
                      "lay-up notation, first ply at the bottom, e.g. \"[0/90]2S\", "
                      "\"[0_2/90_2]S\", \"[0/+-45/90]s\"");
  section->add_option("--material", so.material, "library material for --layup (see 'materials')")
      ->capture_default_str();
  section->add_option("--ply-thickness", so.ply_thickness, "thickness of every ply, with unit");
  section
      ->add_option("--reference", so.reference,
                   "reference surface: mid, bottom, top or a length above the mid-surface")
      ->capture_default_str();
  section->add_option("--json", so.json_path, "write the full result as JSON to this file");
  section->add_flag("--paper", so.paper,
                    "the source paper's lay-ups [theta/-theta]2S (theta = 0..90 by 15) and "
                    "[0/90]2S: table, CSV and JSON in --out");
  section->add_option("-o,--out", so.out_dir, "output directory for --paper")
      ->capture_default_str();
  section
      ->add_option("--vam-order", so.vam_order,
                   "polynomial order of the through-thickness elements (>= 3 gives exact G)")
      ->capture_default_str();

  si::StaticCommandOptions sto;
  auto* static_cmd = app.add_subcommand("static", kStaticHelp);
  static_cmd->add_option("case", sto.case_file, "YAML case file with a load section")
      ->required()
      ->check(CLI::ExistingFile);
  static_cmd->add_option("-o,--out", sto.out_dir,
                         "output directory (default: output.dir of the case file)");
  static_cmd->add_option("--threads", sto.threads, "assembly threads (0: OpenMP default)")
      ->capture_default_str();

  si::RunCommandOptions ro;
  auto* run_cmd = app.add_subcommand("run", kRunHelp);
  run_cmd->add_option("case", ro.case_file, "YAML case file (default: the built-in paper cap)")
      ->check(CLI::ExistingFile);
  run_cmd->add_option("-o,--out", ro.out_dir, "output directory (default: output.dir of the case)");
  run_cmd->add_option("--threads", ro.threads, "assembly threads (0: OpenMP default)")
      ->capture_default_str();
  run_cmd->add_flag("--resume", ro.resume,
                    "continue a stopped continuation run from the checkpoint in the output "
                    "directory (the points before it are kept)");
  si::SweepCommandOptions swo;
  auto* sweep_cmd = app.add_subcommand("sweep", kSweepHelp);
  sweep_cmd->add_option("study", swo.study_file, "YAML study file (docs/sweeps.md)")
      ->check(CLI::ExistingFile);
  sweep_cmd->add_option("-j,--jobs", swo.jobs, "cases run at once (one thread each)")
      ->capture_default_str();
  sweep_cmd->add_option("-o,--out", swo.out_dir, "output directory (default: results/<name>)");
  sweep_cmd->add_flag("--quick", swo.quick,
                      "apply the study's quick: keys (coarse smoke test of the study)");
  sweep_cmd->add_option("--emit", swo.emit_dir,
                        "run nothing: write the cases and DIR/tasks.txt (one shell command per "
                        "case) for a SLURM job array or GNU parallel, then use --collect DIR");
  sweep_cmd->add_option("--collect", swo.collect_dir,
                        "merge the results of the cases emitted into DIR into DIR/sweep.csv "
                        "and sweep.json (the study is optional)");
  sweep_cmd->add_option("--scheduler", swo.scheduler,
                        "run the cases on the Dask cluster at this address (tcp://host:8786) "
                        "through the Python module (docs/sweeps.md)");
  si::FitCommandOptions fo;
  auto* fit_cmd = app.add_subcommand("fit", kFitHelp);
  fit_cmd->add_option("data", fo.data_file, "CSV file with a header line")
      ->required()
      ->check(CLI::ExistingFile);
  fit_cmd->add_option("--model", fo.model, "power, power-log, hertz, power-offset or poly")
      ->required();
  fit_cmd->add_option("--x", fo.x_column, "column of the independent variable")->required();
  fit_cmd->add_option("--y", fo.y_column, "column of the dependent variable")->required();
  fit_cmd->add_option("--degree", fo.degree, "poly: degree N, or auto (default)");
  fit_cmd
      ->add_option("--criterion", fo.criterion, "--degree auto: loo (leave-one-out), aic or aicc")
      ->capture_default_str();
  fit_cmd->add_option("--range", fo.range,
                      "fit only points with x in [a, b]: a:b, a: or :b (negative a: --range=-1:5)");
  fit_cmd->add_option("--json", fo.json_path, "JSON output (default: DATA.fit-MODEL.json)");

  si::CalibrateCommandOptions co;
  auto* calibrate_cmd = app.add_subcommand("calibrate", kCalibrateHelp);
  calibrate_cmd->add_option("case", co.case_file, "YAML case file")
      ->required()
      ->check(CLI::ExistingFile);
  calibrate_cmd->add_option("--data", co.data_file, "measured curve: CSV with units in the header")
      ->required()
      ->check(CLI::ExistingFile);
  calibrate_cmd
      ->add_option("--param", co.params,
                   "KEY=LO:HI[:START] with units, e.g. material.E3=5GPa:20GPa or "
                   "material.nu23=0.2:0.45:0.3 (repeat for each parameter; START default: the "
                   "case's value)")
      ->required()
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  calibrate_cmd->add_option("--x", co.x_column, "travel column (default: the first length column)");
  calibrate_cmd->add_option("--y", co.y_column, "force column (default: the first force column)");
  calibrate_cmd->add_option("-o,--out", co.out_dir,
                            "output directory (default: results/CASE_calibration)");
  calibrate_cmd
      ->add_option("--algorithm", co.settings.algorithm, "bobyqa (derivative-free) or slsqp")
      ->capture_default_str();
  calibrate_cmd
      ->add_option("--max-evaluations", co.settings.max_evaluations,
                   "model evaluations of the search (the Jacobian's 2p come on top)")
      ->capture_default_str();
  calibrate_cmd
      ->add_option("--xtol", co.settings.xtol,
                   "stop when the search's steps are below this fraction of each parameter's range")
      ->capture_default_str();
  calibrate_cmd
      ->add_option("--threads", co.settings.threads,
                   "assembly threads of each run (0: OpenMP's default)")
      ->capture_default_str();
  calibrate_cmd->add_flag("!--no-warm-start", co.settings.warm_start,
                          "run every evaluation's full path from first touch (default: each run "
                          "starts from the nearest earlier run's converged states)");
  calibrate_cmd
      ->add_option("-j,--jobs", co.settings.jobs,
                   "runs at once for the Jacobian at the optimum (the search is sequential)")
      ->capture_default_str();

  auto* materials = app.add_subcommand("materials", "List the built-in material library.");

  std::string notation;
  auto* layup = app.add_subcommand(
      "layup", "Expand lay-up notation ply by ply (bottom to top) and print its compact form.");
  layup->add_option("notation", notation, "e.g. \"[0/+-45/90]s\"")->required();

  // CLI11 would only say "a subcommand is required", for a bare `shellindent` as for a mistyped
  // command: list the commands instead, and suggest the closest one.
  std::vector<std::string> names;
  for (const auto* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  if (argc < 2) {
    std::cerr << kDescription << "\n\n"
              << command_list(app)
              << "\nRun 'shellindent COMMAND --help' for the options of a command.\n";
    return 2;
  }
  if (argv[1][0] != '-' && std::find(names.begin(), names.end(), argv[1]) == names.end())
    throw si::Error(si::ErrorKind::kInput,
                    "unknown command" + si::did_you_mean(argv[1], names) + "\n" + command_list(app),
                    si::Where{"command line", "", argv[1], 0});
  if (const CLI::App* command = argv[1][0] == '-' ? nullptr : app.get_subcommand(argv[1]))
    refuse_unknown_options(*command, argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }

  if (*section) return si::run_section_command(so, std::cout);
  if (*static_cmd) return si::run_static_command(sto, std::cout, std::cerr);
  if (*run_cmd) return si::run_run_command(ro, std::cout, std::cerr);
  if (*sweep_cmd) return si::run_sweep_command(swo, std::cout, std::cerr);
  if (*fit_cmd) return si::run_fit_command(fo, std::cout, std::cerr);
  if (*calibrate_cmd) return si::run_calibrate_command(co, std::cout, std::cerr);
  if (*materials) return si::run_materials_command(std::cout);
  if (*layup) return si::run_layup_command(notation, std::cout);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  si::limit_blas_threads();
  try {
    return run(argc, argv);
  } catch (const si::Error& e) {
    std::cerr << "shellindent: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "shellindent: internal error: " << e.what() << "\n";
    return 3;
  }
}
