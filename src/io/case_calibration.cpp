#include "io/case_calibration.hpp"

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "io/calibration_spellings.hpp"
#include "io/case_file.hpp"
#include "io/case_overrides.hpp"
#include "io/force_travel.hpp"
#include "io/thread_count.hpp"

namespace si {
namespace {

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
                         std::ostream& notes) {
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
    notes << "calibrate: " << name << ": the case's value " << key.value
          << " lies outside the bounds; starting from the middle, " << start << "\n";
  }
  return {key, {name, v[0], v[1], start}};
}

// The case with the parameters at `values`, as YAML text and as read by the case-file reader.
// Thread-safe (the Jacobian's runs read cases concurrently): the YAML is built under a lock.
class CaseWithParameters {
 public:
  CaseWithParameters(std::string label, const std::string& text,
                     const std::vector<Parameter>& params)
      : label_(std::move(label)), root_(YAML::Load(text)), params_(params) {}

  std::string yaml(const Eigen::VectorXd& values) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<NumericValue> set;
    for (std::size_t j = 0; j < params_.size(); ++j)
      set.push_back({params_[j].key.key, params_[j].key.dimension, values[j]});
    YAML::Emitter emitter;
    emitter << with_numeric_values(root_, set, label_);
    return std::string("# ") + label_ + " with " + describe(values) + "\n" + emitter.c_str() + "\n";
  }
  CaseFile read(const Eigen::VectorXd& values) const {
    return parse_case_file(yaml(values), label_ + " (" + describe(values) + ")");
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
  std::string label_;
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

std::vector<Parameter> read_parameters(const CaseCalibrationInput& in, std::ostream& notes) {
  parse_case_file(in.case_text, in.case_label);  // the case itself must be valid: its errors first
  const std::vector<NumericKey> keys = numeric_keys(YAML::Load(in.case_text), in.case_label);
  if (in.params.empty())
    throw_input("nothing to calibrate: give at least one --param KEY=LO:HI[:START]",
                Where{"command line", "--param", "", 0});
  std::vector<Parameter> params;
  for (const std::string& text : in.params) {
    params.push_back(read_parameter(text, keys, notes));
    for (std::size_t j = 0; j + 1 < params.size(); ++j)
      if (params[j].key.key == params.back().key.key)
        throw_input("the parameter is given twice", Where{"command line", "--param", text, 0});
  }
  return params;
}

}  // namespace

struct CaseCalibration::Impl {
  Impl(const CaseCalibrationInput& in, std::vector<Parameter> p)
      : input(in), params(std::move(p)), cases(in.case_label, in.case_text, params) {}
  CaseCalibrationInput input;
  std::vector<Parameter> params;
  CaseWithParameters cases;
  fit::CalibrationAlgorithm algorithm = fit::CalibrationAlgorithm::kDerivativeFree;
  CalibrationContext context;
  Eigen::VectorXd start;
};

CaseCalibration::CaseCalibration(const CaseCalibrationInput& in,
                                 const MeasuredCurveReader& read_data, std::ostream& notes)
    : impl_(std::make_unique<Impl>(in, read_parameters(in, notes))) {
  Impl& s = *impl_;
  s.algorithm = read_choice(YAML::Node(in.settings.algorithm),
                            Where{"command line", "--algorithm", in.settings.algorithm, 0},
                            calibration_algorithm_spellings());
  check_thread_count(in.settings.threads);
  check_parallel_count(in.settings.jobs, "-j", 1, "runs at once");
  const int np = static_cast<int>(s.params.size());
  if (in.settings.max_evaluations < 2 * np + 2)
    throw_input(
        "needs at least 2 p + 2 = " + std::to_string(2 * np + 2),
        Where{"command line", "--max-evaluations", std::to_string(in.settings.max_evaluations), 0});
  s.context = CalibrationContext{in.case_label, read_data(np + 2), {}, in.settings.threads};
  s.start.resize(np);
  for (int j = 0; j < np; ++j) {
    s.start[j] = s.params[j].bounds.start;
    s.context.dimensions.push_back(s.params[j].key.dimension);
  }
  check_corners(s.cases, s.params, s.start);
}

CaseCalibration::~CaseCalibration() = default;

fit::CalibrationResult CaseCalibration::run(
    const std::function<bool(const fit::CalibrationProgress&)>& progress,
    const std::function<bool()>& keep_going) const {
  const Impl& s = *impl_;
  const int np = static_cast<int>(s.params.size());
  const MeasuredCurve& data = s.context.data;
  fit::CalibrationProblem problem;
  for (const Parameter& p : s.params) problem.parameters.push_back(p.bounds);
  problem.x = Eigen::Map<const Eigen::VectorXd>(data.travel.data(), data.travel.size());
  problem.y = Eigen::Map<const Eigen::VectorXd>(data.force.data(), data.force.size());
  Eigen::VectorXd width(np);
  for (int j = 0; j < np; ++j) width[j] = s.params[j].bounds.upper - s.params[j].bounds.lower;
  WarmStarts warm(width);
  const bool warm_start = s.input.settings.warm_start;
  problem.model = [&](const Eigen::VectorXd& c) {
    fit::ModelOutput m;
    try {
      const std::optional<ForceTravelStates> from = warm_start ? warm.nearest(c) : std::nullopt;
      ForceTravel f = run_force_travel(s.cases.read(c), data.travel, s.input.settings.threads,
                                       keep_going, from ? &*from : nullptr);
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
  settings.algorithm = s.algorithm;
  settings.max_evaluations = s.input.settings.max_evaluations;
  settings.xtol = s.input.settings.xtol;
  settings.concurrent_evaluations = s.input.settings.jobs;
  settings.progress = progress;
  return fit::calibrate(problem, settings);
}

const CalibrationContext& CaseCalibration::context() const {
  return impl_->context;
}

std::string CaseCalibration::case_yaml(const Eigen::VectorXd& values) const {
  return impl_->cases.yaml(values);
}

std::string CaseCalibration::progress_line(const fit::CalibrationProgress& p) const {
  char tail[160];
  if (p.ok)
    std::snprintf(tail, sizeof tail, "S = %.6g N^2 (best %.6g), %.1f s, %s", p.sse, p.best_sse,
                  p.seconds, p.note.c_str());
  else
    std::snprintf(tail, sizeof tail, "failed (%.1f s): ", p.seconds);
  return "calibrate: " + std::to_string(p.evaluation) +
         (p.phase == fit::CalibrationPhase::kSearch ? " search   " : " jacobian ") +
         impl_->cases.describe(p.parameters) + ": " + tail + (p.ok ? "" : p.failure);
}

std::string CaseCalibration::header_line() const {
  const Impl& s = *impl_;
  const MeasuredCurve& data = s.context.data;
  std::ostringstream os;
  os << "calibrate: " << s.input.case_label << " against " << data.file << ": "
     << data.travel.size() << " points, travel " << data.travel.front() << " to "
     << data.travel.back() << " mm, " << s.params.size() << " parameter(s), "
     << fit::calibration_algorithm_name(s.algorithm) << ", at most "
     << s.input.settings.max_evaluations << " search evaluations";
  return os.str();
}

}  // namespace si
