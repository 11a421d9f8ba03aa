#include "io/critical_points_json.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace si {
namespace {

using nlohmann::json;

json number(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

json point_json(const CriticalPoint& c) {
  json j = {{"type", critical_kind_name(c.kind)},
            {"depth_mm", number(c.depth)},
            {"force_N", number(c.force)},
            {"accuracy_mm", number(c.accuracy)},
            {"located", c.located}};
  if (std::isfinite(c.stiffness)) j["tangent_stiffness_N_per_mm"] = c.stiffness;
  if (std::isfinite(c.linear_force)) j["linear_force_N"] = c.linear_force;
  return j;
}

json list_json(const std::vector<CriticalPoint>& points) {
  json list = json::array();
  for (const CriticalPoint& c : points) list.push_back(point_json(c));
  return list;
}

std::string format(const char* pattern, double a, double b, double c) {
  char buf[160];
  std::snprintf(buf, sizeof buf, pattern, a, b, c);
  return buf;
}

// "stiffness_min at depth 1.234 mm, force 567.8 N (+-0.01 mm)" for each point, or "none".
std::string list_text(const std::vector<CriticalPoint>& points) {
  if (points.empty()) return "none";
  std::string text;
  for (const CriticalPoint& c : points)
    text += (text.empty() ? "" : "; ") + std::string(critical_kind_name(c.kind)) +
            format(" at depth %.6g mm, force %.6g N (+-%.2g mm)", c.depth, c.force, c.accuracy);
  return text;
}

const char* const kSweepColumns[][2] = {
    {"nonlinearity_onset_depth_mm", "nonlinearity_onset_force_N"},
    {"stiffness_min_depth_mm", "stiffness_min_force_N"},
    {"limit_point_depth_mm", "limit_point_force_N"},
    {"bifurcation_depth_mm", "bifurcation_force_N"}};

}  // namespace

const char* critical_kind_name(CriticalKind kind) {
  // In CriticalKind's order.
  const char* const names[] = {"nonlinearity_onset", "stiffness_min", "stiffness_max", "depth_turn",
                               "force_max",          "force_min",     "bifurcation"};
  return names[static_cast<int>(kind)];
}

const char* onset_status_name(OnsetStatus status) {
  // In OnsetStatus's order.
  const char* const names[] = {"found",     "none",           "linear_kinematics",
                               "local_law", "too_few_points", "support_frame"};
  return names[static_cast<int>(status)];
}

json critical_points_json(const CriticalPoints& p) {
  json onset = {{"status", onset_status_name(p.onset_status)},
                {"fraction", p.nonlinearity_fraction}};
  if (p.onset) onset.update(point_json(*p.onset));
  onset.erase("type");
  if (p.onset_status == OnsetStatus::kNone) onset["max_deviation"] = number(p.max_deviation);
  return {{"nonlinearity_onset", onset},
          {"force_inflections", list_json(p.inflections)},
          {"limit_points", list_json(p.limit_points)},
          {"bifurcations", p.stability ? list_json(p.bifurcations) : json(nullptr)}};
}

std::vector<std::string> critical_points_summary(const CriticalPoints& p) {
  std::string onset = "critical point: nonlinearity onset (" +
                      format("%.3g %%", 100 * p.nonlinearity_fraction, 0, 0) + " from linear): ";
  switch (p.onset_status) {
    case OnsetStatus::kFound:
      onset += format("depth %.6g mm, force %.6g N (+-%.2g mm)", p.onset->depth, p.onset->force,
                      p.onset->accuracy);
      break;
    case OnsetStatus::kNone:
      onset += format("none on the path (largest deviation %.3g %%)", 100 * p.max_deviation, 0, 0);
      break;
    case OnsetStatus::kLinearKinematics:
      onset += "none: the run has linear kinematics";
      break;
    case OnsetStatus::kLocalLaw:
      onset += "not computed with a local contact law (contact.local)";
      break;
    case OnsetStatus::kTooFewPoints:
      onset += "not computed: too few points";
      break;
    case OnsetStatus::kSupportFrame:
      onset += "not computed with a support frame (fixture)";
      break;
  }
  return {onset, "critical point: inflections of T(h): " + list_text(p.inflections),
          "critical point: limit points: " + list_text(p.limit_points),
          "critical point: bifurcations: " +
              (p.stability ? list_text(p.bifurcations)
                           : std::string("not looked for (path.stability: false)"))};
}

const std::vector<std::string>& critical_point_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> c;
    for (const auto& pair : kSweepColumns) c.insert(c.end(), {pair[0], pair[1]});
    return c;
  }();
  return columns;
}

void summarize_critical_points(const json& path, json& row) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  const json none = json::object();
  const json& c = path.contains("critical_points") ? path["critical_points"] : none;
  const auto value = [](const json& point, const char* key) {
    return point.contains(key) && point[key].is_number() ? point[key].get<double>() : kNan;
  };
  const auto first = [&](const char* list, const char* type) {
    if (c.contains(list) && c[list].is_array())
      for (const json& point : c[list])
        if (type == nullptr || point.value("type", "") == type) return point;
    return none;
  };
  const json found[] = {c.value("nonlinearity_onset", none),
                        first("force_inflections", critical_kind_name(CriticalKind::kStiffnessMin)),
                        first("limit_points", nullptr), first("bifurcations", nullptr)};
  for (int k = 0; k < 4; ++k) {
    row[kSweepColumns[k][0]] = value(found[k], "depth_mm");
    row[kSweepColumns[k][1]] = value(found[k], "force_N");
  }
}

}  // namespace si
