#include "io/named_sets_reader.hpp"

#include <map>
#include <string>

#include "io/spellings.hpp"

namespace si {
namespace {

const Choices<SupportType> kSupportTypes{{"clamped", SupportType::kClamped},
                                         {"hinged", SupportType::kHinged},
                                         {"simply_supported", SupportType::kSimplySupported},
                                         {"symmetry", SupportType::kSymmetry},
                                         {"displacement", SupportType::kDisplacement},
                                         {"free", SupportType::kFree}};
const Choices<int> kAxes{{"x", 0}, {"y", 1}, {"z", 2}};
const Choices<NamedLoadType> kLoadTypes{{"point", NamedLoadType::kPoint},
                                        {"moment", NamedLoadType::kMoment},
                                        {"edge", NamedLoadType::kEdge},
                                        {"pressure", NamedLoadType::kPressure}};

// Prescribed-displacement keys: translations (length) and rotations (angle).
const std::vector<std::pair<std::string, SupportDof>> kDofs{{"u_x", SupportDof::kUx},
                                                            {"u_y", SupportDof::kUy},
                                                            {"u_z", SupportDof::kUz},
                                                            {"theta_1", SupportDof::kTheta1},
                                                            {"theta_2", SupportDof::kTheta2}};

// The entries of a list-valued top-level key, each a map with its own dotted path.
std::vector<MapReader> entries(const MapReader& top, const std::string& key) {
  const YAML::Node list = top.at(key);
  const Where list_where = top.where(key);
  if (!list.IsSequence() || list.size() == 0)
    throw_input("expected a non-empty list of entries such as {on: x-, type: clamped}", list_where);
  std::vector<MapReader> out;
  for (std::size_t i = 0; i < list.size(); ++i)
    out.emplace_back(list[i], Where{list_where.file, key + "[" + std::to_string(i) + "]",
                                    text_of(list[i]), line_of(list[i])});
  return out;
}

// A list of three quantities; `dimension_text` renames the dimension in unit errors (a force per
// length shares its unit with the fracture toughness).
Vector3d read_vector(const MapReader& map, const std::string& key, Dimension dim,
                     const std::string& dimension_text = "") {
  const YAML::Node node = map.at(key);
  if (!node.IsSequence() || node.size() != 3)
    throw_input("expected a list of three values, e.g. [0 N, 0 N, -10 N]", map.where(key));
  Vector3d v;
  for (int i = 0; i < 3; ++i) {
    try {
      v[i] = parse_quantity(text_of(node[static_cast<std::size_t>(i)]), dim);
    } catch (const Error& e) {
      std::string reason = e.reason();
      const std::string from = dimension_name(dim);
      for (std::size_t at = reason.find(from); !dimension_text.empty() && at != std::string::npos;
           at = reason.find(from))
        reason.replace(at, from.size(), dimension_text);
      throw Error(e.kind(), reason, e.where()).within(map.where(key));
    }
  }
  return v;
}

NamedSupportSpec read_support(const MapReader& entry) {
  NamedSupportSpec s;
  s.type = entry.choice("type", kSupportTypes);
  std::vector<std::string> allowed{"on", "type"};
  if (s.type == SupportType::kSymmetry) allowed.push_back("normal");
  if (s.type == SupportType::kDisplacement)
    for (const auto& dof : kDofs) allowed.push_back(dof.first);
  entry.allow_only(allowed);
  s.on = entry.scalar("on");
  s.where = entry.where("on");
  if (s.type == SupportType::kSymmetry) s.symmetry_axis = entry.choice_or("normal", kAxes, -1);
  if (s.type != SupportType::kDisplacement) return s;
  for (const auto& [name, dof] : kDofs) {
    if (!entry.has(name)) continue;
    const bool rotation = dof == SupportDof::kTheta1 || dof == SupportDof::kTheta2;
    s.values.push_back(
        {dof, entry.quantity(name, rotation ? Dimension::kAngle : Dimension::kLength)});
  }
  if (s.values.empty())
    throw_input(
        "a displacement support needs at least one of u_x, u_y, u_z (lengths) or "
        "theta_1, theta_2 (angles, 0 only)",
        entry.where());
  return s;
}

// A point force or moment is placed by a named set or by a position, never both.
void require_one_of_on_at(const MapReader& entry, const std::string& what) {
  if (entry.has("on") == entry.has("at"))
    throw_input(what +
                    " needs exactly one of `on` (a named set) and `at` (a position: the "
                    "nearest node is loaded)",
                entry.where());
}

NamedLoadSpec read_load(const MapReader& entry) {
  NamedLoadSpec l;
  l.type = entry.choice("type", kLoadTypes);
  l.where = entry.where();
  switch (l.type) {
    case NamedLoadType::kPoint:
      entry.allow_only({"type", "on", "at", "force"});
      require_one_of_on_at(entry, "a point load");
      if (entry.has("at")) l.at = read_vector(entry, "at", Dimension::kLength);
      l.vector = read_vector(entry, "force", Dimension::kForce);
      break;
    case NamedLoadType::kMoment:
      // A moment has the unit of an energy (N mm, N m); the messages say "moment".
      entry.allow_only({"type", "on", "at", "moment"});
      require_one_of_on_at(entry, "a moment");
      if (entry.has("at")) l.at = read_vector(entry, "at", Dimension::kLength);
      l.vector = read_vector(entry, "moment", Dimension::kEnergy, "moment");
      break;
    case NamedLoadType::kEdge:
      entry.allow_only({"type", "on", "force_per_length", "moment_per_length"});
      if (!entry.has("force_per_length") && !entry.has("moment_per_length"))
        throw_input("an edge load needs `force_per_length`, `moment_per_length` or both",
                    entry.where());
      if (entry.has("force_per_length"))
        l.vector = read_vector(entry, "force_per_length", Dimension::kFractureToughness,
                               "force per length");
      // N mm/mm is a force: the messages say "moment per length".
      if (entry.has("moment_per_length"))
        l.moment = read_vector(entry, "moment_per_length", Dimension::kForce, "moment per length");
      break;
    case NamedLoadType::kPressure:
      entry.allow_only({"type", "on", "pressure", "follower"});
      l.pressure = entry.quantity("pressure", Dimension::kStress);
      l.follower = entry.choice_or("follower", boolean_spellings(), false);
      break;
  }
  if (entry.has("on")) {
    l.on = entry.scalar("on");
    l.where = entry.where("on");
  } else if (l.type == NamedLoadType::kEdge) {
    entry.at("on");  // "missing key"
  }
  return l;
}

std::string type_name(SupportType t) {
  for (const auto& [name, value] : kSupportTypes)
    if (value == t) return name;
  return "?";
}

}  // namespace

std::vector<NamedSupportSpec> read_supports(const MapReader& top) {
  if (!top.has("supports")) return {};
  std::vector<NamedSupportSpec> out;
  std::map<std::string, const NamedSupportSpec*> by_set;
  for (const MapReader& entry : entries(top, "supports")) out.push_back(read_support(entry));
  for (const NamedSupportSpec& s : out) {
    const auto [it, inserted] = by_set.emplace(s.on, &s);
    if (inserted) continue;
    const NamedSupportSpec& first = *it->second;
    throw_input(first.type == s.type
                    ? "'" + s.on + "' is given a support twice (first at line " +
                          std::to_string(first.where.line) + ")"
                    : "conflicting supports on '" + s.on + "': " + type_name(first.type) +
                          " (line " + std::to_string(first.where.line) + ") and " +
                          type_name(s.type) + "; give one entry per set",
                s.where);
  }
  return out;
}

std::vector<NamedLoadSpec> read_named_loads(const MapReader& top) {
  if (!top.has("loads")) return {};
  std::vector<NamedLoadSpec> out;
  for (const MapReader& entry : entries(top, "loads")) out.push_back(read_load(entry));
  return out;
}

}  // namespace si
