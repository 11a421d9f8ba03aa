#include "io/fixture_reader.hpp"

#include <cmath>

#include "io/plausible_range.hpp"

namespace si {
namespace {

const Choices<FixtureType> kFixtureTypes{{"astm_d7136", FixtureType::kAstmD7136},
                                         {"astm_d6264_opening", FixtureType::kAstmD6264Opening},
                                         {"astm_d6264_backed", FixtureType::kAstmD6264Backed}};

// A list of two lengths, e.g. [125 mm, 75 mm]; `positive`: both > 0.
Vector2d read_pair(const YAML::Node& node, const Where& where, bool positive) {
  if (!node.IsSequence() || node.size() != 2)
    throw_input("expected a list of two lengths, e.g. [125 mm, 75 mm]", where);
  Vector2d v;
  for (int i = 0; i < 2; ++i) {
    try {
      v[i] = parse_quantity(text_of(node[i]), Dimension::kLength);
    } catch (const Error& e) {
      throw e.within(where);
    }
    if (std::abs(v[i]) > kLengthRange.max) check_plausible(std::abs(v[i]), kLengthRange, where);
    if (positive && !(v[i] > 0)) throw_input("both lengths must be positive", where);
  }
  return v;
}

std::vector<Vector2d> read_clamps(const MapReader& map) {
  const YAML::Node node = map.at("clamps");
  if (!node.IsSequence())
    throw_input("expected a list of clamp tip positions, e.g. [[50 mm, 43.75 mm], ...]",
                map.where("clamps"));
  std::vector<Vector2d> clamps;
  for (const YAML::Node& tip : node) {
    Where where = map.where("clamps");
    where.value = text_of(tip);
    where.line = line_of(tip) ? line_of(tip) : where.line;
    clamps.push_back(read_pair(tip, where, false));
  }
  return clamps;
}

// The plate the fixture holds: `shell` may give a rectangular plate's size (a mesh file: only its
// edge), and its edge must be free.
void check_shell(const MapReader& top, const MapReader& fixture, ShellSpec& shell) {
  const bool imported = top.has("mesh") && top.at("mesh").IsMap() && top.at("mesh")["file"];
  if (!top.has("shell") && !imported) {
    shell.type = ShellType::kRectangularPlate;
    shell.length_x = kFixtureSpecimenX;
    shell.length_y = kFixtureSpecimenY;
  }
  if (top.has("shell")) {
    const MapReader map(top.at("shell"), top.where("shell"));
    if (!imported && shell.type != ShellType::kRectangularPlate)
      throw_input("a fixture holds a rectangular plate (" + fixture.scalar("type") + ")",
                  map.where("type"));
    if (map.has("edge") && shell.edge != EdgeCondition::kFree)
      throw_input("the plate rests on the fixture's frame: its edges are free (omit shell.edge)",
                  map.where("edge"));
  }
  shell.edge = EdgeCondition::kFree;
}

}  // namespace

FixtureSpec read_fixture(const MapReader& top, ShellSpec& shell) {
  FixtureSpec f;
  if (!top.has("fixture")) return f;
  const MapReader map(top.at("fixture"), top.where("fixture"));
  f.type = map.choice("type", kFixtureTypes);
  switch (f.type) {
    case FixtureType::kAstmD7136: {
      map.allow_only({"type", "window", "clamps"});
      if (map.has("window")) {
        const Vector2d w = read_pair(map.at("window"), map.where("window"), true);
        f.window_x = w.x();
        f.window_y = w.y();
      }
      f.clamps = map.has("clamps") ? read_clamps(map) : astm_d7136_clamps();
      break;
    }
    case FixtureType::kAstmD6264Opening:
      map.allow_only({"type", "opening_diameter", "clamps"});
      f.opening_diameter = map.positive("opening_diameter", Dimension::kLength);
      if (map.has("clamps")) f.clamps = read_clamps(map);
      break;
    case FixtureType::kAstmD6264Backed:
    case FixtureType::kNone:
      map.allow_only({"type", "clamps"});
      if (map.has("clamps")) f.clamps = read_clamps(map);
      break;
  }
  check_shell(top, map, shell);
  return f;
}

}  // namespace si
