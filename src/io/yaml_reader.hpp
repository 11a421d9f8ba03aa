// Reading values out of yaml-cpp nodes so that every error names the file, the dotted key, the
// value as written and the 1-based line (yaml-cpp marks are 0-based).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "core/units.hpp"

namespace si {

// 1-based line of a node, 0 when yaml-cpp has no mark for it.
int line_of(const YAML::Node& node);

// The node as the user wrote it: the scalar text, or a one-line rendering of a map or list.
std::string text_of(const YAML::Node& node);

// The node's scalar text; throws if it is a map, a list or empty.
std::string read_scalar(const YAML::Node& node, const Where& where);

// A quantity with its unit ("0.475 mm"), converted to internal units; unit errors carry `where`.
double read_quantity(const YAML::Node& node, const Where& where, Dimension dim);

// Allowed spellings of an enum-valued key and the values they stand for.
template <class E>
using Choices = std::vector<std::pair<std::string, E>>;

// Index in `names` of the node's text; unknown spellings are refused with the allowed list.
size_t read_choice_index(const YAML::Node& node, const Where& where,
                         const std::vector<std::string>& names);

// The enum value spelled by `node`.
template <class E>
E read_choice(const YAML::Node& node, const Where& where, const Choices<E>& choices) {
  std::vector<std::string> names;
  for (const auto& c : choices) names.push_back(c.first);
  return choices[read_choice_index(node, where, names)].second;
}

// A YAML map being read at a known dotted path of a known file. Keys that are absent are reported
// at where.line, the line of the key that holds the map (0 at the top level: no line to point at).
class MapReader {
 public:
  // Throws unless `node` is a map. `where.key` is the map's dotted path ("" at the top level).
  MapReader(const YAML::Node& node, Where where);

  // Refuses any key not in `allowed` (the message lists them and suggests the closest one) and
  // any key given twice (yaml-cpp would silently keep one of them).
  void allow_only(const std::vector<std::string>& allowed) const;

  bool has(const std::string& key) const;
  // The value at `key`; throws "missing key" if absent.
  YAML::Node at(const std::string& key) const;
  // Dotted path of a child key: "laminate" + "ply_thickness" -> "laminate.ply_thickness".
  std::string path(const std::string& key) const;
  // Context of a child: its path, and its value and line when present.
  Where where(const std::string& key) const;
  const Where& where() const { return where_; }
  const YAML::Node& node() const { return node_; }

  std::string scalar(const std::string& key) const;
  std::string scalar_or(const std::string& key, const std::string& fallback) const;
  double quantity(const std::string& key, Dimension dim) const;
  double quantity_or(const std::string& key, Dimension dim, double fallback) const;
  // As quantity(), and refuses values <= 0 (lengths, thicknesses, moduli).
  double positive(const std::string& key, Dimension dim) const;
  double positive_or(const std::string& key, Dimension dim, double fallback) const;
  int integer_or(const std::string& key, int fallback) const;

  // The enum value spelled at `key`; unknown spellings are refused with the allowed list.
  template <class E>
  E choice_or(const std::string& key, const Choices<E>& choices, E fallback) const {
    return has(key) ? read_choice(at(key), where(key), choices) : fallback;
  }
  template <class E>
  E choice(const std::string& key, const Choices<E>& choices) const {
    return read_choice(at(key), where(key), choices);
  }

 private:
  YAML::Node node_;
  Where where_;
};

// map[key]: a non-empty list of names (plain scalars), each once; errors name the entry (key[i]).
std::vector<std::string> read_name_list(const MapReader& map, const std::string& key);

}  // namespace si
