#include "io/material_reader.hpp"

#include <optional>

#include "core/did_you_mean.hpp"
#include "core/units.hpp"
#include "core/value_excerpt.hpp"
#include "io/plausible_range.hpp"
#include "io/yaml_reader.hpp"
#include "material/material_library.hpp"

namespace si {
namespace {

const Choices<bool> kMaterialTypes{{"orthotropic", false}, {"isotropic", true}};

std::string last_key_part(const std::string& key) {
  const size_t dot = key.rfind('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out.empty() ? "none" : out;
}

Material read_library_material(const YAML::Node& node, const Where& context) {
  const std::string name = read_scalar(node, context);
  try {
    return library_material(name);
  } catch (const Error& e) {
    throw Error(e.kind(), e.reason() + did_you_mean(name, library_material_names()), context);
  }
}

// Material's validation names the constant ("nu12"); point the user at it in the file, with the
// value as written. Errors about several constants at once (positive definiteness) are reported
// at the whole material; their reason names the constants.
Error at_constant(const Error& e, const MapReader& map) {
  const std::string& constant = e.where().key;
  if (map.has(constant)) return Error(e.kind(), e.reason(), map.where(constant));
  Where w = map.where();
  w.value = e.where().value;
  return Error(e.kind(), e.reason(), w);
}

// The failure-property keys (material/ply_strengths.hpp), nested under `strengths:` /
// `toughness:` or flat beside the elastic constants.
std::vector<std::string> strength_keys() {
  std::vector<std::string> keys;
  for (int k = 0; k < kStrengthKeys; ++k) keys.emplace_back(key_name(StrengthKey(k)));
  return keys;
}
std::vector<std::string> toughness_keys() {
  std::vector<std::string> keys;
  for (int k = 0; k < kToughnessKeys; ++k) keys.emplace_back(key_name(ToughnessKey(k)));
  return keys;
}

// One failure property, nested or flat; given both ways is refused (which one would count?).
template <class Key, class Values>
void read_failure_value(const MapReader& map, const MapReader* nested, Key key, Dimension dim,
                        Values& values) {
  const std::string name = key_name(key);
  if (nested != nullptr && nested->has(name) && map.has(name))
    throw_input(name + " is given twice: under '" + nested->where().key + "' and beside it",
                map.where(name));
  const MapReader& source = (nested != nullptr && nested->has(name)) ? *nested : map;
  if (!source.has(name)) return;
  const double value = source.quantity(name, dim);
  if (!(value > 0.0))
    throw_input(name + " must be positive (a strength or toughness is a magnitude)",
                source.where(name));
  values.set(key, value);
}

// `strengths: {...}`, `toughness: {...}` and the flat keys of an inline material.
Material with_failure_properties(const Material& m, const MapReader& map) {
  std::optional<MapReader> strengths, toughness;
  if (map.has("strengths")) {
    strengths.emplace(map.at("strengths"), map.where("strengths"));
    strengths->allow_only(strength_keys());
  }
  if (map.has("toughness")) {
    toughness.emplace(map.at("toughness"), map.where("toughness"));
    toughness->allow_only(toughness_keys());
  }
  PlyStrengths s;
  for (int k = 0; k < kStrengthKeys; ++k)
    read_failure_value(map, strengths ? &*strengths : nullptr, StrengthKey(k), Dimension::kStress,
                       s);
  FractureToughness t;
  for (int k = 0; k < kToughnessKeys; ++k)
    read_failure_value(map, toughness ? &*toughness : nullptr, ToughnessKey(k),
                       Dimension::kFractureToughness, t);
  return m.with_failure_properties(s, t);
}

// The keys an inline material of this type accepts: its constants and the failure properties.
std::vector<std::string> inline_keys(std::vector<std::string> constants) {
  constants.insert(constants.end(), {"type", "name", "strengths", "toughness"});
  for (const auto& k : strength_keys()) constants.push_back(k);
  for (const auto& k : toughness_keys()) constants.push_back(k);
  return constants;
}

// A modulus as written, within the plausible range (io/plausible_range.hpp); its sign is the
// material's to check (it names the constant in its message).
double read_modulus(const MapReader& map, const std::string& key) {
  const double value = map.quantity(key, Dimension::kStress);
  if (value > 0.0) check_plausible(value, kModulusRange, map.where(key));
  return value;
}

Material read_elastic_constants(const MapReader& map, const std::string& name, bool isotropic) {
  if (isotropic) {
    map.allow_only(inline_keys({"E", "nu"}));
    const double E = read_modulus(map, "E");
    const double nu = map.quantity("nu", Dimension::kDimensionless);
    try {
      return Material::isotropic(name, E, nu);
    } catch (const Error& e) {
      throw at_constant(e, map);
    }
  }
  map.allow_only(inline_keys({"E1", "E2", "E3", "G12", "G13", "G23", "nu12", "nu13", "nu23"}));
  EngineeringConstants c;
  c.E1 = read_modulus(map, "E1");
  c.E2 = read_modulus(map, "E2");
  c.E3 = read_modulus(map, "E3");
  c.G12 = read_modulus(map, "G12");
  c.G13 = read_modulus(map, "G13");
  c.G23 = read_modulus(map, "G23");
  c.nu12 = map.quantity("nu12", Dimension::kDimensionless);
  c.nu13 = map.quantity("nu13", Dimension::kDimensionless);
  c.nu23 = map.quantity("nu23", Dimension::kDimensionless);
  try {
    return Material::orthotropic(name, c);
  } catch (const Error& e) {
    throw at_constant(e, map);
  }
}

Material read_inline_material(const MapReader& map) {
  const std::string name = map.scalar_or("name", last_key_part(map.where().key));
  const bool isotropic = map.choice("type", kMaterialTypes);
  return with_failure_properties(read_elastic_constants(map, name, isotropic), map);
}

std::vector<std::string> entry_names(const YAML::Node& map) {
  std::vector<std::string> names;
  for (const auto& entry : map) names.push_back(entry.first.Scalar());
  return names;
}

}  // namespace

Material read_material(const YAML::Node& node, const Where& context) {
  if (node.IsMap()) return read_inline_material(MapReader(node, context));
  return read_library_material(node, context);
}

std::vector<Material> read_material_map(const YAML::Node& node, const Where& context) {
  const MapReader map(node, context);
  map.allow_only(entry_names(node));  // refuses duplicated names
  std::vector<Material> materials;
  for (const auto& entry : node) {
    const std::string name = entry.first.Scalar();
    materials.push_back(read_material(entry.second, map.where(name)).renamed(name));
  }
  return materials;
}

Material MaterialTable::find(const std::string& name, const Where& where) const {
  for (const auto& m : named)
    if (m.name() == name) return m;
  if (default_material.name() == name) return default_material;
  const auto library = library_material_names();
  for (const auto& l : library)
    if (l == name) return library_material(name);

  std::vector<std::string> defined{default_material.name()};
  for (const auto& m : named) defined.push_back(m.name());
  std::vector<std::string> all = defined;
  all.insert(all.end(), library.begin(), library.end());
  throw_input("undefined material '" + value_excerpt(name) + "'" + did_you_mean(name, all) +
                  "; defined in the file: " + join(defined) + "; library: " + join(library),
              where);
}

}  // namespace si
