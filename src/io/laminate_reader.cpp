#include "io/laminate_reader.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/units.hpp"
#include "io/yaml_reader.hpp"
#include "section/layup_notation.hpp"

namespace si {
namespace {

// Plies of a lay-up string: one ply per angle, all of one material and thickness.
std::vector<Ply> read_layup_group(const MapReader& map, const MaterialTable& materials) {
  const std::string notation = map.scalar("layup");
  std::vector<double> angles;
  try {
    angles = parse_layup(notation);
  } catch (const Error& e) {
    throw e.within(map.where("layup"));
  }
  const double thickness = map.positive("ply_thickness", Dimension::kLength);
  const Material material = map.has("material")
                                ? materials.find(map.scalar("material"), map.where("material"))
                                : materials.default_material;
  std::vector<Ply> plies;
  for (double angle : angles) plies.push_back(Ply{material, thickness, angle});
  return plies;
}

Ply read_single_ply(const MapReader& map, const MaterialTable& materials) {
  const Material material = map.has("material")
                                ? materials.find(map.scalar("material"), map.where("material"))
                                : materials.default_material;
  return Ply{material, map.positive("thickness", Dimension::kLength),
             map.quantity_or("angle", Dimension::kAngle, 0.0)};
}

std::vector<Ply> read_ply_list(const MapReader& laminate, const MaterialTable& materials) {
  const YAML::Node list = laminate.at("plies");
  const Where list_where = laminate.where("plies");
  if (!list.IsSequence() || list.size() == 0)
    throw_input("expected a non-empty list of plies and ply groups", list_where);
  std::vector<Ply> plies;
  for (size_t i = 0; i < list.size(); ++i) {
    const Where entry_where{list_where.file, list_where.key + "[" + std::to_string(i) + "]",
                            text_of(list[i]), line_of(list[i])};
    const MapReader entry(list[i], entry_where);
    if (entry.has("layup")) {
      entry.allow_only({"layup", "ply_thickness", "material"});
      for (auto& p : read_layup_group(entry, materials)) plies.push_back(p);
    } else {
      entry.allow_only({"material", "thickness", "angle", "layup"});
      plies.push_back(read_single_ply(entry, materials));
    }
  }
  return plies;
}

// Offset of the reference surface above the mid-surface for a laminate of thickness h.
double read_reference(const MapReader& laminate, double h) {
  if (!laminate.has("reference")) return 0.0;
  try {
    return parse_reference_surface(laminate.scalar("reference"), h);
  } catch (const Error& e) {
    throw e.within(laminate.where("reference"));
  }
}

}  // namespace

Laminate read_laminate(const YAML::Node& node, const Where& context,
                       const MaterialTable& materials) {
  const MapReader map(node, context);
  Laminate laminate;
  if (map.has("plies")) {
    map.allow_only({"plies", "reference"});
    laminate.plies = read_ply_list(map, materials);
  } else if (map.has("layup")) {
    map.allow_only({"layup", "ply_thickness", "material", "reference"});
    laminate.plies = read_layup_group(map, materials);
  } else {
    throw_input("give either 'layup' with 'ply_thickness', or a list 'plies'", map.where());
  }
  laminate.reference_offset = read_reference(map, laminate.thickness());
  try {
    laminate.validate();
  } catch (const Error& e) {
    throw e.within(map.where());
  }
  return laminate;
}

double parse_reference_surface(const std::string& text, double h) {
  if (text == "mid") return 0.0;
  if (text == "bottom") return -0.5 * h;
  if (text == "top") return 0.5 * h;
  double offset = 0;
  try {
    offset = parse_quantity(text, Dimension::kLength);
  } catch (const Error& e) {
    throw_input("expected mid, bottom, top or a length above the mid-surface such as '0.2 mm' (" +
                e.reason() + ")");
  }
  if (std::abs(offset) > 0.5 * h) {
    throw_input("the reference surface must lie within the laminate: |offset| <= h/2 = " +
                format_quantity(0.5 * h, Dimension::kLength));
  }
  return offset;
}

}  // namespace si
