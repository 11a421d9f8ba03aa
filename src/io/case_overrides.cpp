#include "io/case_overrides.hpp"

#include <cstdio>

#include "core/did_you_mean.hpp"
#include "io/material_reader.hpp"
#include "io/study_file.hpp"
#include "io/yaml_reader.hpp"
#include "material/material_library.hpp"

namespace si {
namespace {

// "9500 MPa", with every digit a double carries (the YAML round trip must not move the value).
std::string quantity_text(double value, Dimension dim) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return dim == Dimension::kDimensionless ? std::string(buf)
                                          : std::string(buf) + " " + internal_unit(dim);
}

bool is_material(const YAML::Node& node) {
  return node && !node.IsNull() && text_of(node) != "rigid";
}

// The elastic constants of `m` as key -> value pairs, in the order of docs/case-file.md.
std::vector<std::pair<std::string, double>> constants_of(const Material& m) {
  const EngineeringConstants& c = m.constants();
  if (m.is_isotropic()) return {{"E", c.E1}, {"nu", c.nu12}};
  return {{"E1", c.E1},   {"E2", c.E2},     {"E3", c.E3},     {"G12", c.G12},  {"G13", c.G13},
          {"G23", c.G23}, {"nu12", c.nu12}, {"nu13", c.nu13}, {"nu23", c.nu23}};
}

Dimension dimension_of(const std::string& constant) {
  return constant.rfind("nu", 0) == 0 ? Dimension::kDimensionless : Dimension::kStress;
}

// A library material as the inline table the case-file reader accepts.
YAML::Node inline_table(const Material& m) {
  YAML::Node t(YAML::NodeType::Map);
  t["type"] = m.is_isotropic() ? "isotropic" : "orthotropic";
  t["name"] = m.name();
  for (const auto& [key, value] : constants_of(m)) t[key] = quantity_text(value, dimension_of(key));
  for (int k = 0; k < kStrengthKeys; ++k)
    if (const auto v = m.strengths().get(StrengthKey(k)))
      t[key_name(StrengthKey(k))] = quantity_text(*v, Dimension::kStress);
  for (int k = 0; k < kToughnessKeys; ++k)
    if (const auto v = m.toughness().get(ToughnessKey(k)))
      t[key_name(ToughnessKey(k))] = quantity_text(*v, Dimension::kFractureToughness);
  return t;
}

// The material nodes of a case: (dotted key, node).
std::vector<std::pair<std::string, YAML::Node>> material_nodes(const YAML::Node& root) {
  std::vector<std::pair<std::string, YAML::Node>> out;
  if (is_material(root["material"])) out.emplace_back("material", root["material"]);
  if (root["materials"] && root["materials"].IsMap())
    for (const auto& entry : root["materials"])
      out.emplace_back("materials." + entry.first.Scalar(), entry.second);
  if (root["indenter"] && root["indenter"].IsMap() && is_material(root["indenter"]["material"]))
    out.emplace_back("indenter.material", root["indenter"]["material"]);
  return out;
}

std::string join(const std::vector<NumericKey>& keys) {
  std::string out;
  for (const auto& k : keys) out += (out.empty() ? "" : ", ") + k.key;
  return out;
}

}  // namespace

std::vector<NumericKey> numeric_keys(const YAML::Node& root, const std::string& file) {
  std::vector<NumericKey> keys;
  for (const auto& [key, node] : material_nodes(root)) {
    const Material m = read_material(node, Where{file, key, text_of(node), line_of(node)});
    for (const auto& [constant, value] : constants_of(m))
      keys.push_back({key + "." + constant, dimension_of(constant), value});
  }
  const YAML::Node laminate = root["laminate"];
  if (laminate && laminate.IsMap() && laminate["ply_thickness"])
    keys.push_back(
        {"laminate.ply_thickness", Dimension::kLength,
         read_quantity(laminate["ply_thickness"], Where{file, "laminate.ply_thickness", "", 0},
                       Dimension::kLength)});
  return keys;
}

const NumericKey& find_numeric_key(const std::vector<NumericKey>& keys, const std::string& name,
                                   const Where& where) {
  std::vector<std::string> names;
  for (const auto& k : keys) {
    if (k.key == name) return k;
    names.push_back(k.key);
  }
  throw_input("not a parameter of this case" + did_you_mean(name, names) +
                  "; the case's numeric keys are: " + join(keys),
              where);
}

YAML::Node with_numeric_values(const YAML::Node& root, const std::vector<NumericValue>& values,
                               const std::string& file) {
  YAML::Node out = YAML::Clone(root);
  for (const auto& [key, node] : material_nodes(out)) {
    bool touched = false;
    for (const NumericValue& v : values) touched = touched || v.key.rfind(key + ".", 0) == 0;
    if (!touched || node.IsMap()) continue;
    const Material m = read_material(node, Where{file, key, text_of(node), line_of(node)});
    set_dotted_key(out, key, inline_table(m), Where{file, key, text_of(node), line_of(node)});
  }
  for (const NumericValue& v : values)
    set_dotted_key(out, v.key, YAML::Node(quantity_text(v.value, v.dimension)),
                   Where{file, v.key, "", 0});
  return out;
}

}  // namespace si
