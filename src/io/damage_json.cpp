#include "io/damage_json.hpp"

#include <cmath>

#include "analysis/path_columns.hpp"
#include "io/spellings.hpp"

namespace si {
namespace {

// JSON has no NaN: null where a value does not exist.
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json threshold_json(const DelaminationThreshold& t, double depth) {
  return {{"method", "Davies & Zhang (1995), n delaminations (Suemasu & Majima)"},
          {"load_N", t.load},
          {"stiffness", spelling(bending_stiffness_spellings(), t.stiffness)},
          {"D_effective_Nmm", t.D_effective},
          {"D11_Nmm", t.D11},
          {"D22_Nmm", t.D22},
          {"D12_Nmm", t.D12},
          {"D66_Nmm", t.D66},
          {"anisotropy", t.anisotropy},
          {"G_IIc_N_per_mm", t.G_IIc},
          {"delaminations", t.delaminations},
          {"path_depth_mm", number(depth)}};
}

nlohmann::json energy_json(const EnergyPoint& e) {
  return {{"energy_Nmm", e.energy},
          {"outcome", spelling(energy_outcome_spellings(), e.outcome)},
          {column_name(PathColumn::kDepth), number(e.depth)},
          {column_name(PathColumn::kForce), number(e.force)},
          {"max_work_Nmm", e.max_work}};
}

}  // namespace

nlohmann::json onset_json(const DamageOnset& o) {
  nlohmann::json j = {{"criterion", spelling(criterion_spellings(), o.criterion)},
                      {"mode", spelling(failure_mode_spellings(), o.at.mode)},
                      {"x3_mm", o.at.x3},
                      {"node", o.at.node},
                      {column_name(PathColumn::kDepth), o.depth},
                      {column_name(PathColumn::kForce), number(o.force)},
                      {column_name(PathColumn::kWork), o.work},
                      {"located", o.located},
                      {"accuracy", o.accuracy}};
  if (o.at.interface) {
    j["interface"] = {o.at.ply, o.at.ply + 1};  // between plies k and k + 1 (1-based)
  } else {
    j["ply"] = o.at.ply + 1;
    j["position"] = spelling(ply_position_spellings(), o.at.position);
  }
  return j;
}

nlohmann::json damage_json(const IndentationSetup& setup, const PathResult& result) {
  const DamageSpec& spec = *setup.spec.damage;
  nlohmann::json criteria = nlohmann::json::array();
  for (Criterion c : spec.criteria) criteria.push_back(spelling(criterion_spellings(), c));
  nlohmann::json onsets = nlohmann::json::array();
  for (const DamageOnset& o : result.damage.onsets) onsets.push_back(onset_json(o));
  nlohmann::json energies = nlohmann::json::array();
  for (const EnergyPoint& e : result.damage.energies) energies.push_back(energy_json(e));
  nlohmann::json j = {{"criteria", criteria},
                      {"recovery", spelling(recovery_spellings(), spec.recovery)},
                      {"onsets", onsets},
                      {"impact_energies", energies}};
  if (setup.damage) {
    j["monitored_nodes"] = setup.damage->monitored().size();
    nlohmann::json points = nlohmann::json::object();
    for (const auto& [name, node] : setup.damage->reported()) points[name] = node;
    j["points"] = points;
  }
  if (result.damage.threshold)
    j["threshold"] = threshold_json(*result.damage.threshold, result.damage.threshold_depth);
  return j;
}

}  // namespace si
