#include "io/damage_reader.hpp"

#include <algorithm>

#include "damage/criterion_strengths.hpp"
#include "io/spellings.hpp"

namespace si {
namespace {

// The entry `i` of the list at `key`, for messages: "damage.criteria[1]".
Where entry_where(const MapReader& map, const std::string& key, const YAML::Node& list,
                  std::size_t i) {
  const Where w = map.where(key);
  return {w.file, w.key + "[" + std::to_string(i) + "]", text_of(list[i]), line_of(list[i])};
}

YAML::Node list_at(const MapReader& map, const std::string& key, const char* example) {
  const YAML::Node list = map.at(key);
  if (!list.IsSequence())
    throw_input(std::string("expected a list, e.g. ") + example, map.where(key));
  return list;
}

// Each criterion once; every ply's material must carry the strengths it reads.
std::vector<Criterion> read_criteria(const MapReader& map, const Laminate& laminate) {
  const YAML::Node list = list_at(map, "criteria", "[hashin, delamination]");
  if (list.size() == 0) throw_input("name at least one criterion", map.where("criteria"));
  std::vector<Criterion> criteria;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Where w = entry_where(map, "criteria", list, i);
    const Criterion c = read_choice(list[i], w, criterion_spellings());
    if (std::find(criteria.begin(), criteria.end(), c) != criteria.end())
      throw_input("the criterion is listed twice", w);
    for (const Ply& ply : laminate.plies) {
      try {
        strengths_for(c, ply.material);
      } catch (const Error& e) {
        throw_input(e.reason(), w);  // names the material and the key
      }
    }
    criteria.push_back(c);
  }
  return criteria;
}

// `apex` or {name: ..., position: [x, y, z]}.
std::vector<DamagePoint> read_points(const MapReader& map) {
  const YAML::Node list =
      list_at(map, "points", "[apex, {name: p1, position: [5 mm, 0 mm, 0 mm]}]");
  std::vector<DamagePoint> points;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Where w = entry_where(map, "points", list, i);
    if (list[i].IsScalar() && text_of(list[i]) == "apex") continue;  // always reported
    if (!list[i].IsMap()) throw_input("expected `apex` or {name: ..., position: [x, y, z]}", w);
    const MapReader point(list[i], Where{w.file, w.key, "", w.line});
    point.allow_only({"name", "position"});
    DamagePoint p;
    p.name = point.scalar("name");
    if (p.name == "apex") throw_input("the name `apex` is the apex's own", point.where("name"));
    for (const DamagePoint& q : points)
      if (q.name == p.name) throw_input("two points have this name", point.where("name"));
    const YAML::Node xyz = point.at("position");
    if (!xyz.IsSequence() || xyz.size() != 3)
      throw_input("expected a list of three lengths, e.g. [5 mm, 0 mm, 0 mm]",
                  point.where("position"));
    for (int k = 0; k < 3; ++k)
      p.position[k] = read_quantity(xyz[k], point.where("position"), Dimension::kLength);
    points.push_back(p);
  }
  return points;
}

std::vector<double> read_energies(const MapReader& map) {
  const YAML::Node list = list_at(map, "impact_energies", "[1 J, 2.5 J]");
  std::vector<double> energies;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Where w = entry_where(map, "impact_energies", list, i);
    const double e = read_quantity(list[i], w, Dimension::kEnergy);
    if (!(e > 0)) throw_input("an impact energy must be > 0", w);
    energies.push_back(e);
  }
  return energies;
}

// Davies-Zhang reads G_IIc of the interfaces: every ply's material must carry it.
ThresholdSpec read_threshold(const MapReader& damage, const Laminate& laminate) {
  const MapReader map(damage.at("threshold"), damage.where("threshold"));
  map.allow_only({"stiffness", "delaminations"});
  ThresholdSpec t;
  t.stiffness = map.choice_or("stiffness", bending_stiffness_spellings(), t.stiffness);
  t.delaminations = map.integer_or("delaminations", t.delaminations);
  if (t.delaminations < 1) throw_input("must be a whole number >= 1", map.where("delaminations"));
  for (const Ply& ply : laminate.plies)
    if (!ply.material.toughness().get(ToughnessKey::kGIIc))
      throw_input("material '" + ply.material.name() +
                      "' has no G_IIc, which the Davies-Zhang delamination threshold needs",
                  damage.where("threshold"));
  return t;
}

}  // namespace

std::optional<DamageSpec> read_damage(const MapReader& top, const Laminate& laminate) {
  if (!top.has("damage")) return std::nullopt;
  const MapReader map(top.at("damage"), top.where("damage"));
  map.allow_only({"criteria", "points", "recovery", "face_pressure", "patch_radius", "radius",
                  "impact_energies", "threshold"});
  DamageSpec d;
  if (map.has("criteria")) d.criteria = read_criteria(map, laminate);
  if (map.has("points")) d.points = read_points(map);
  d.recovery = map.choice_or("recovery", recovery_spellings(), d.recovery);
  d.face_pressure = map.choice_or("face_pressure", face_pressure_spellings(), d.face_pressure);
  if (map.has("patch_radius")) {
    d.patch_radius = map.quantity("patch_radius", Dimension::kLength);
    if (!(d.patch_radius >= 0))
      throw_input("expected a length >= 0 (0: the 25 nearest nodes only)",
                  map.where("patch_radius"));
  }
  d.radius = map.positive_or("radius", Dimension::kLength, 0.0);
  if (map.has("impact_energies")) d.impact_energies = read_energies(map);
  if (map.has("threshold")) d.threshold = read_threshold(map, laminate);
  if (d.criteria.empty() && d.impact_energies.empty() && !d.threshold)
    throw_input("give at least one of criteria, impact_energies or threshold", map.where());
  return d;
}

}  // namespace si
