#include "io/material_reader.hpp"

#include "core/units.hpp"
#include "core/value_excerpt.hpp"
#include "io/did_you_mean.hpp"
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

// A modulus as written, within the plausible range (io/plausible_range.hpp); its sign is the
// material's to check (it names the constant in its message).
double read_modulus(const MapReader& map, const std::string& key) {
  const double value = map.quantity(key, Dimension::kStress);
  if (value > 0.0) check_plausible(value, kModulusRange, map.where(key));
  return value;
}

Material read_inline_material(const MapReader& map) {
  const std::string name = map.scalar_or("name", last_key_part(map.where().key));
  const bool isotropic = map.choice("type", kMaterialTypes);
  if (isotropic) {
    map.allow_only({"type", "name", "E", "nu"});
    const double E = read_modulus(map, "E");
    const double nu = map.quantity("nu", Dimension::kDimensionless);
    try {
      return Material::isotropic(name, E, nu);
    } catch (const Error& e) {
      throw at_constant(e, map);
    }
  }
  map.allow_only({"type", "name", "E1", "E2", "E3", "G12", "G13", "G23", "nu12", "nu13", "nu23"});
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

std::vector<std::string> entry_names(const YAML::Node& map) {
  std::vector<std::string> names;
  for (const auto& entry : map) names.push_back(entry.first.Scalar());
  return names;
}

// Material has no setter for its name: rebuild it (the constants were validated already).
Material renamed(const Material& m, const std::string& name) {
  const EngineeringConstants& c = m.constants();
  return m.is_isotropic() ? Material::isotropic(name, c.E1, c.nu12)
                          : Material::orthotropic(name, c);
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
    materials.push_back(renamed(read_material(entry.second, map.where(name)), name));
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
