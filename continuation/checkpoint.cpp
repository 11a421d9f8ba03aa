#include "continuation/checkpoint.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace si::cont {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "si.cont.checkpoint";
constexpr int kVersion = 1;

// Finite doubles are JSON numbers: nlohmann_json 3.11 prints the shortest decimal that reads
// back to the same double (Grisu2 + round trip), so they are exact. JSON has no inf/NaN: those
// are the strings "inf", "-inf", "nan".
json number(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

double to_double(const json& j) {
  if (j.is_number()) return j.get<double>();
  const auto s = j.get<std::string>();
  if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  throw std::runtime_error("not a number: '" + s + "'");
}

json vector(const Vector& v) {
  json a = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(number(v(i)));
  return a;
}

Vector to_vector(const json& j) {
  Vector v(static_cast<Eigen::Index>(j.size()));
  for (std::size_t i = 0; i < j.size(); ++i) v(static_cast<Eigen::Index>(i)) = to_double(j[i]);
  return v;
}

// Keys written only when set, so that the checkpoints of runs without stability, curve features
// or branch switching keep their version-1 form byte for byte; read back with defaults.
void add_optional(json& j, const Point& p) {
  if (p.monitor_curvature_errors.size() > 0) {
    j["monitor_curvature_errors"] = vector(p.monitor_curvature_errors);
    j["parameter_curvature"] = number(p.parameter_curvature);
    j["parameter_curvature_error"] = number(p.parameter_curvature_error);
  }
  if (p.negative_eigenvalues >= 0) {
    j["negative_eigenvalues"] = p.negative_eigenvalues;
    j["zero_eigenvalues"] = p.zero_eigenvalues;
    j["stable"] = p.stable;
    j["lowest_eigenvalue"] = number(p.lowest_eigenvalue);
    j["eigenvalues"] = vector(p.eigenvalues);
  }
  if (p.branch_id != 0) j["branch_id"] = p.branch_id;
}

void read_optional(const json& j, Point& p) {
  if (j.contains("monitor_curvature_errors")) {
    p.monitor_curvature_errors = to_vector(j.at("monitor_curvature_errors"));
    p.parameter_curvature = to_double(j.at("parameter_curvature"));
    p.parameter_curvature_error = to_double(j.at("parameter_curvature_error"));
  }
  if (j.contains("negative_eigenvalues")) {
    p.negative_eigenvalues = j.at("negative_eigenvalues").get<int>();
    p.zero_eigenvalues = j.at("zero_eigenvalues").get<int>();
    p.stable = j.at("stable").get<bool>();
    p.lowest_eigenvalue = to_double(j.at("lowest_eigenvalue"));
    p.eigenvalues = to_vector(j.at("eigenvalues"));
  }
  p.branch_id = j.value("branch_id", 0);
}

json point_json(const Point& p, bool with_x = true) {
  json j = {{"x", with_x ? vector(p.x) : json::array()},
            {"p", number(p.p)},
            {"tangent_p", number(p.tangent_p)},
            {"monitors", vector(p.monitors)},
            {"monitor_slopes", vector(p.monitor_slopes)},
            {"monitor_curvatures", vector(p.monitor_curvatures)},
            {"signature", p.signature},
            {"jacobian_sign", p.jacobian_sign},
            {"newton_iterations", p.newton_iterations},
            {"step", number(p.step)},
            {"arclength", number(p.arclength)}};
  add_optional(j, p);
  return j;
}

Point to_point(const json& j) {
  Point p;
  p.x = to_vector(j.at("x"));
  p.p = to_double(j.at("p"));
  p.tangent_p = to_double(j.at("tangent_p"));
  p.monitors = to_vector(j.at("monitors"));
  p.monitor_slopes = to_vector(j.at("monitor_slopes"));
  p.monitor_curvatures = to_vector(j.at("monitor_curvatures"));
  p.signature = j.at("signature").get<std::vector<int>>();
  p.jacobian_sign = j.at("jacobian_sign").get<int>();
  p.newton_iterations = j.at("newton_iterations").get<int>();
  p.step = to_double(j.at("step"));
  p.arclength = to_double(j.at("arclength"));
  read_optional(j, p);
  return p;
}

json event_json(const Event& e, bool with_x) {
  json j = {{"type", e.name},
            {"monitor", e.monitor},
            {"against", e.against},
            {"p", number(e.p)},
            {"x", with_x ? vector(e.x) : json::array()},
            {"monitors", vector(e.monitors)},
            {"step", e.step},
            {"located", e.located},
            {"accuracy", number(e.accuracy)},
            {"arclength", number(e.arclength)}};
  if (e.branch_id != 0) j["branch_id"] = e.branch_id;
  if (e.criticality != Criticality::kNone) {
    j["criticality"] = criticality_name(e.criticality);
    j["negative_before"] = e.negative_before;
    j["negative_after"] = e.negative_after;
    j["eigenvalue"] = number(e.eigenvalue);
    j["mode"] = with_x ? vector(e.mode) : json::array();
    j["tangent_x"] = with_x ? vector(e.tangent_x) : json::array();
    j["tangent_p"] = number(e.tangent_p);
  }
  return j;
}

Criticality to_criticality(const std::string& name) {
  for (Criticality c : {Criticality::kNone, Criticality::kLimitPoint, Criticality::kBifurcation})
    if (criticality_name(c) == name) return c;
  throw std::runtime_error("unknown criticality '" + name + "'");
}

EventType to_event_type(const std::string& name) {
  for (EventType t : {EventType::kLimitPoint, EventType::kMonitorMax, EventType::kMonitorMin,
                      EventType::kZeroCrossing, EventType::kSignatureChange, EventType::kInflection,
                      EventType::kBifurcation, EventType::kStabilityChange, EventType::kSlopeMax,
                      EventType::kSlopeMin})
    if (event_type_name(t) == name) return t;
  throw std::runtime_error("unknown event type '" + name + "'");
}

Event to_event(const json& j) {
  Event e;
  e.name = j.at("type").get<std::string>();
  e.type = to_event_type(e.name);
  e.monitor = j.at("monitor").get<std::string>();
  e.against = j.at("against").get<std::string>();
  e.p = to_double(j.at("p"));
  e.x = to_vector(j.at("x"));
  e.monitors = to_vector(j.at("monitors"));
  e.step = j.at("step").get<int>();
  e.located = j.at("located").get<bool>();
  e.accuracy = to_double(j.at("accuracy"));
  e.arclength = to_double(j.at("arclength"));
  e.branch_id = j.value("branch_id", 0);
  if (j.contains("criticality")) {
    e.criticality = to_criticality(j.at("criticality").get<std::string>());
    e.negative_before = j.at("negative_before").get<int>();
    e.negative_after = j.at("negative_after").get<int>();
    e.eigenvalue = to_double(j.at("eigenvalue"));
    e.mode = to_vector(j.at("mode"));
    e.tangent_x = to_vector(j.at("tangent_x"));
    e.tangent_p = to_double(j.at("tangent_p"));
  }
  return e;
}

Status to_status(const std::string& name) {
  for (Status s : {Status::kRunning, Status::kCompleted, Status::kReachedBound, Status::kMaxSteps,
                   Status::kStepTooSmall, Status::kStoppedByCallback, Status::kStartFailed})
    if (status_name(s) == name) return s;
  throw std::runtime_error("unknown status '" + name + "'");
}

json branch_json(const Branch& b, bool points_x) {
  json points = json::array();
  for (const auto& p : b.points) points.push_back(point_json(p, points_x));
  json events = json::array();
  for (const auto& e : b.events) events.push_back(event_json(e, points_x));
  return {
      {"monitor_names", b.monitor_names}, {"points", points},   {"events", events},
      {"status", status_name(b.status)},  {"reason", b.reason}, {"failed_steps", b.failed_steps}};
}

Branch to_branch(const json& j) {
  Branch b;
  b.monitor_names = j.at("monitor_names").get<std::vector<std::string>>();
  for (const auto& p : j.at("points")) b.points.push_back(to_point(p));
  for (const auto& e : j.at("events")) b.events.push_back(to_event(e));
  b.status = to_status(j.at("status").get<std::string>());
  b.reason = j.at("reason").get<std::string>();
  b.failed_steps = j.at("failed_steps").get<int>();
  return b;
}

json state_json(const State& s) {
  return {{"current", point_json(s.current.point)},
          {"tangent_x", vector(s.current.tangent_x)},
          {"step", number(s.step)},
          {"has_previous", s.has_previous},
          {"previous_x", vector(s.previous_x)},
          {"previous_p", number(s.previous_p)},
          {"previous_tangent_p", number(s.previous_tangent_p)}};
}

State to_state(const json& j) {
  State s;
  s.current.point = to_point(j.at("current"));
  s.current.tangent_x = to_vector(j.at("tangent_x"));
  s.step = to_double(j.at("step"));
  s.has_previous = j.at("has_previous").get<bool>();
  s.previous_x = to_vector(j.at("previous_x"));
  s.previous_p = to_double(j.at("previous_p"));
  // Absent from checkpoints written before 2026-11-30: no previous slope, Keller's next step.
  s.previous_tangent_p = to_double(j.value("previous_tangent_p", json("nan")));
  return s;
}

}  // namespace

std::string checkpoint_text(const Checkpoint& checkpoint, bool points_x) {
  json j = {{"format", kFormat},
            {"version", kVersion},
            {"method", method_name(checkpoint.method)},
            {"branch", branch_json(checkpoint.branch, points_x)},
            {"state", state_json(checkpoint.state)}};
  if (!checkpoint.attachment.is_null()) j["attachment"] = checkpoint.attachment;
  return j.dump() + '\n';
}

void save_checkpoint(const std::string& path, const Checkpoint& checkpoint, bool points_x,
                     const FileWriter& write) {
  if (!write) throw std::invalid_argument("save_checkpoint: no file writer");
  write(path, checkpoint_text(checkpoint, points_x));
}

Checkpoint load_checkpoint(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read checkpoint '" + path + "'");
  try {
    const json j = json::parse(in);
    if (j.at("format").get<std::string>() != kFormat || j.at("version").get<int>() != kVersion)
      throw std::runtime_error("not a version-1 continuation checkpoint");
    Checkpoint c;
    c.method = parse_method(j.at("method").get<std::string>());
    c.branch = to_branch(j.at("branch"));
    c.state = to_state(j.at("state"));
    if (j.contains("attachment")) c.attachment = j.at("attachment");
    return c;
  } catch (const std::exception& e) {
    throw std::runtime_error("checkpoint '" + path + "': " + e.what());
  }
}

}  // namespace si::cont
