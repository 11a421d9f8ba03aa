#include "app/calibrate_command.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>

#include "app/interrupt_signals.hpp"
#include "app/thread_count.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "fitting/calibration.hpp"
#include "io/calibration_report.hpp"
#include "io/calibration_spellings.hpp"
#include "io/case_file.hpp"
#include "io/case_overrides.hpp"
#include "io/force_travel.hpp"
#include "io/measured_curve.hpp"
#include "io/output_directory.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// "5GPa:20GPa:10GPa", "5:20 GPa", "0.2:0.45" -> values in internal units. A bare number takes
// the unit written last on the right of it, so "5:20 GPa" is 5 GPa to 20 GPa.
std::vector<double> read_bounds(const std::string& text, Dimension dim, const Where& where) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ':');) parts.push_back(trim(part));
  if (parts.size() < 2 || parts.size() > 3 || text.back() == ':')
    throw_input("expected KEY=LO:HI or KEY=LO:HI:START", where);
  std::vector<double> values;
  std::string unit;
  for (auto p = parts.rbegin(); p != parts.rend(); ++p) {
    char* end = nullptr;
    std::strtod(p->c_str(), &end);
    const std::string own = trim(end);
    if (!own.empty()) unit = own;
    try {
      values.insert(values.begin(),
                    parse_quantity(own.empty() && !unit.empty() ? *p + " " + unit : *p, dim));
    } catch (const Error& e) {
      throw Error(ErrorKind::kInput, e.reason(), where);
    }
  }
  return values;
}

struct Parameter {
  NumericKey key;
  fit::CalibrationParameter bounds;
};

Parameter read_parameter(const std::string& text, const std::vector<NumericKey>& keys,
                         std::ostream& err) {
  const Where where{"command line", "--param", text, 0};
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw_input("expected KEY=LO:HI[:START]", where);
  const std::string name = trim(text.substr(0, eq));
  const NumericKey& key = find_numeric_key(keys, name, Where{"command line", "--param", name, 0});
  const std::vector<double> v = read_bounds(text.substr(eq + 1), key.dimension, where);
  if (!(v[0] < v[1])) throw_input("the bounds are inverted or equal: LO must be below HI", where);
  double start = v.size() == 3 ? v[2] : key.value;
  if (v.size() == 3 && !(v[0] <= start && start <= v[1]))
    throw_input("START lies outside [LO, HI]", where);
  if (v.size() == 2 && !(v[0] <= start && start <= v[1])) {
    start = 0.5 * (v[0] + v[1]);
    err << "calibrate: " << name << ": the case's value " << key.value
        << " lies outside the bounds; starting from the middle, " << start << "\n";
  }
  return {key, {name, v[0], v[1], start}};
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The case with the parameters at `values`, as YAML text and as read by the case-file reader.
// Thread-safe (the Jacobian's runs read cases concurrently): the YAML is built under a lock.
class CaseWithParameters {
 public:
  CaseWithParameters(std::string file, const std::vector<Parameter>& params)
      : file_(std::move(file)), root_(YAML::Load(read_text(file_))), params_(params) {}

  std::string yaml(const Eigen::VectorXd& values) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<NumericValue> set;
    for (std::size_t j = 0; j < params_.size(); ++j)
      set.push_back({params_[j].key.key, params_[j].key.dimension, values[j]});
    YAML::Emitter emitter;
    emitter << with_numeric_values(root_, set, file_);
    return std::string("# ") + file_ + " with " + describe(values) + "\n" + emitter.c_str() + "\n";
  }
  CaseFile read(const Eigen::VectorXd& values) const {
    return parse_case_file(yaml(values), file_ + " (" + describe(values) + ")");
  }
  std::string describe(const Eigen::VectorXd& values) const {
    std::string s;
    for (std::size_t j = 0; j < params_.size(); ++j) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.6g", values[j]);
      const Dimension d = params_[j].key.dimension;
      s += (s.empty() ? "" : ", ") + params_[j].key.key + " = " + buf +
           (d == Dimension::kDimensionless ? "" : " " + internal_unit(d));
    }
    return s;
  }

 private:
  std::string file_;
  YAML::Node root_;
  std::vector<Parameter> params_;
  mutable std::mutex mutex_;
};

// The converged states of recent evaluations: a new run starts from those of the nearest one
// (parameters measured relative to their ranges), io/force_travel.hpp's warm start. Thread-safe.
class WarmStarts {
 public:
  explicit WarmStarts(Eigen::VectorXd width) : width_(std::move(width)) {}

  std::optional<ForceTravelStates> nearest(const Eigen::VectorXd& c) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const Entry* best = nullptr;
    for (const Entry& e : kept_)
      if (!best || distance(e.c, c) < distance(best->c, c)) best = &e;
    return best ? std::optional<ForceTravelStates>(best->states) : std::nullopt;
  }
  void add(const Eigen::VectorXd& c, ForceTravelStates states) {
    const std::lock_guard<std::mutex> lock(mutex_);
    kept_.push_back({c, std::move(states)});
    if (kept_.size() > kKept) kept_.erase(kept_.begin());
  }

 private:
  struct Entry {
    Eigen::VectorXd c;
    ForceTravelStates states;
  };
  static constexpr std::size_t kKept = 4;
  double distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    return (a - b).cwiseQuotient(width_).norm();
  }
  Eigen::VectorXd width_;
  std::vector<Entry> kept_;
  mutable std::mutex mutex_;
};

// Every bound must give a valid case (with the other parameters at their starts): a modulus
// bound of 0, or a Poisson ratio that breaks positive definiteness, is refused before any run.
void check_corners(const CaseWithParameters& c, const std::vector<Parameter>& params,
                   const Eigen::VectorXd& start) {
  c.read(start);
  for (std::size_t j = 0; j < params.size(); ++j)
    for (const double bound : {params[j].bounds.lower, params[j].bounds.upper}) {
      Eigen::VectorXd v = start;
      v[j] = bound;
      try {
        c.read(v);
      } catch (const Error& e) {
        throw Error(
            ErrorKind::kInput, "this bound gives an invalid case (" + e.reason() + ")",
            Where{"command line", "--param " + params[j].key.key, std::to_string(bound), 0});
      }
    }
}

std::string progress_line(const fit::CalibrationProgress& p, const CaseWithParameters& c) {
  char tail[160];
  if (p.ok)
    std::snprintf(tail, sizeof tail, "S = %.6g N^2 (best %.6g), %.1f s, %s", p.sse, p.best_sse,
                  p.seconds, p.note.c_str());
  else
    std::snprintf(tail, sizeof tail, "failed (%.1f s): ", p.seconds);
  return "calibrate: " + std::to_string(p.evaluation) +
         (p.phase == fit::CalibrationPhase::kSearch ? " search   " : " jacobian ") +
         c.describe(p.parameters) + ": " + tail + (p.ok ? "" : p.failure);
}

}  // namespace

int run_calibrate_command(const CalibrateCommandOptions& o, std::ostream& out, std::ostream& err) {
  read_case_file(o.case_file);  // the case itself must be valid: its own errors first
  const YAML::Node root = YAML::Load(read_text(o.case_file));
  const std::vector<NumericKey> keys = numeric_keys(root, o.case_file);
  if (o.params.empty())
    throw_input("nothing to calibrate: give at least one --param KEY=LO:HI[:START]",
                Where{"command line", "--param", "", 0});
  std::vector<Parameter> params;
  for (const std::string& text : o.params) {
    params.push_back(read_parameter(text, keys, err));
    for (std::size_t j = 0; j + 1 < params.size(); ++j)
      if (params[j].key.key == params.back().key.key)
        throw_input("the parameter is given twice", Where{"command line", "--param", text, 0});
  }
  const fit::CalibrationAlgorithm algorithm =
      read_choice(YAML::Node(o.algorithm), Where{"command line", "--algorithm", o.algorithm, 0},
                  calibration_algorithm_spellings());
  check_thread_count(o.threads);
  check_parallel_count(o.jobs, "-j", 1, "runs at once");
  if (o.max_evaluations < 2 * static_cast<int>(params.size()) + 2)
    throw_input("needs at least 2 p + 2 = " + std::to_string(2 * params.size() + 2),
                Where{"command line", "--max-evaluations", std::to_string(o.max_evaluations), 0});
  const int np = static_cast<int>(params.size());
  CalibrationContext context{
      o.case_file, read_measured_curve(o.data_file, o.x_column, o.y_column, np + 2), {}, o.threads};
  Eigen::VectorXd start(np);
  fit::CalibrationProblem problem;
  for (int j = 0; j < np; ++j) {
    start[j] = params[j].bounds.start;
    problem.parameters.push_back(params[j].bounds);
    context.dimensions.push_back(params[j].key.dimension);
  }
  const CaseWithParameters cases(o.case_file, params);
  check_corners(cases, params, start);
  const fs::path dir =
      o.out_dir.empty()
          ? fs::path("results") / (fs::path(o.case_file).stem().string() + "_calibration")
          : fs::path(o.out_dir);
  prepare_output_directory(dir, Where{"command line", "--out", dir.string(), 0});

  const MeasuredCurve& data = context.data;
  problem.x = Eigen::Map<const Eigen::VectorXd>(data.travel.data(), data.travel.size());
  problem.y = Eigen::Map<const Eigen::VectorXd>(data.force.data(), data.force.size());
  Eigen::VectorXd width(np);
  for (int j = 0; j < np; ++j) width[j] = params[j].bounds.upper - params[j].bounds.lower;
  WarmStarts warm(width);
  problem.model = [&](const Eigen::VectorXd& c) {
    fit::ModelOutput m;
    try {
      const std::optional<ForceTravelStates> from = o.warm_start ? warm.nearest(c) : std::nullopt;
      ForceTravel f = run_force_travel(
          cases.read(c), data.travel, o.threads, [] { return !interrupted(); },
          from ? &*from : nullptr);
      m.ok = f.ok;
      m.failure = f.failure;
      m.predicted = Eigen::Map<const Eigen::VectorXd>(f.force.data(), f.force.size());
      m.note = std::string(f.warm ? "warm" : "cold") + " start, " +
               std::to_string(f.newton_iterations) + " Newton iterations";
      if (f.ok) warm.add(c, std::move(f.states));
    } catch (const Error& e) {  // a parameter combination the case-file reader refuses
      m.failure = e.what();
    }
    return m;
  };
  fit::CalibrationSettings settings;
  settings.algorithm = algorithm;
  settings.max_evaluations = o.max_evaluations;
  settings.xtol = o.xtol;
  settings.concurrent_evaluations = o.jobs;
  settings.progress = [&](const fit::CalibrationProgress& p) {
    err << progress_line(p, cases) << std::endl;
    return !interrupted();
  };
  err << "calibrate: " << o.case_file << " against " << data.file << ": " << data.travel.size()
      << " points, travel " << data.travel.front() << " to " << data.travel.back() << " mm, " << np
      << " parameter(s), " << fit::calibration_algorithm_name(algorithm) << ", at most "
      << o.max_evaluations << " search evaluations\n";
  fit::CalibrationResult r;
  {
    InterruptGuard guard;
    r = fit::calibrate(problem, settings);
  }
  if (r.status == fit::CalibrationStatus::kInterrupted)
    err << "calibrate: interrupted (" << interrupt_name() << ")\n";

  write_file_atomically((dir / "calibration.json").string(),
                        calibration_json(context, r).dump(2) + "\n");
  write_file_atomically((dir / "calibration_curve.csv").string(),
                        calibration_curve_csv(context, r));
  if (r.parameters.size() == np)
    write_file_atomically((dir / "calibrated_case.yaml").string(), cases.yaml(r.parameters));
  out << calibration_table(context, r);
  err << "wrote " << (dir / "calibration.json").string()
      << ", calibration_curve.csv and calibrated_case.yaml\n";
  return r.status == fit::CalibrationStatus::kConverged ? 0 : 1;
}

}  // namespace si
