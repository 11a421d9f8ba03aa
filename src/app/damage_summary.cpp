#include "app/damage_summary.hpp"

#include <algorithm>

#include "io/spellings.hpp"

namespace si {
namespace {

std::string energy_prefix(std::size_t i) {
  return "impact_" + std::to_string(i + 1) + "_";
}

}  // namespace

std::vector<std::string> damage_columns(const std::vector<StudyCase>& cases) {
  std::vector<Criterion> criteria;
  std::size_t energies = 0;
  bool threshold = false;
  for (const StudyCase& c : cases) {
    if (!c.case_file.damage) continue;
    const DamageSpec& d = *c.case_file.damage;
    for (Criterion k : d.criteria)
      if (std::find(criteria.begin(), criteria.end(), k) == criteria.end()) criteria.push_back(k);
    energies = std::max(energies, d.impact_energies.size());
    threshold = threshold || d.threshold.has_value();
  }
  std::vector<std::string> cols;
  for (const auto& [name, criterion] : criterion_spellings())  // in the spellings' order
    if (std::find(criteria.begin(), criteria.end(), criterion) != criteria.end())
      for (const char* field : {"depth_mm", "force_N", "work_Nmm", "mode"})
        cols.push_back("onset_" + name + "_" + field);
  if (threshold)
    for (const char* c : {"delamination_threshold_N", "delamination_threshold_depth_mm",
                          "delamination_threshold_D_Nmm", "G_IIc_N_per_mm"})
      cols.push_back(c);
  for (std::size_t i = 0; i < energies; ++i)
    for (const char* field : {"energy_Nmm", "depth_mm", "force_N", "outcome"})
      cols.push_back(energy_prefix(i) + field);
  return cols;
}

void summarize_damage(const nlohmann::json& path, nlohmann::json& row) {
  if (!path.contains("damage")) return;
  const nlohmann::json& d = path["damage"];
  for (const nlohmann::json& o : d.value("onsets", nlohmann::json::array())) {
    const std::string prefix = "onset_" + o.value("criterion", std::string()) + "_";
    if (row.contains(prefix + "depth_mm")) continue;  // the first onset (by depth) only
    row[prefix + "depth_mm"] = o["depth_mm"];
    row[prefix + "force_N"] = o["force_N"];
    row[prefix + "work_Nmm"] = o["work_Nmm"];
    row[prefix + "mode"] = o["mode"];
  }
  if (d.contains("threshold")) {
    const nlohmann::json& t = d["threshold"];
    row["delamination_threshold_N"] = t["load_N"];
    row["delamination_threshold_depth_mm"] = t["path_depth_mm"];
    row["delamination_threshold_D_Nmm"] = t["D_effective_Nmm"];
    row["G_IIc_N_per_mm"] = t["G_IIc_N_per_mm"];
  }
  const nlohmann::json energies = d.value("impact_energies", nlohmann::json::array());
  for (std::size_t i = 0; i < energies.size(); ++i)
    for (const char* field : {"energy_Nmm", "depth_mm", "force_N", "outcome"})
      row[energy_prefix(i) + field] = energies[i][field];
}

}  // namespace si
