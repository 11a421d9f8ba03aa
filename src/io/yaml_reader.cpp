#include "io/yaml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <set>

#include "core/did_you_mean.hpp"
#include "core/value_excerpt.hpp"
#include "io/plausible_range.hpp"

namespace si {
namespace {

constexpr size_t kMaxValueText = 60;  // longer values are cut in messages

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string kind_of(const YAML::Node& node) {
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  if (node.IsNull()) return "nothing";
  return "a single value";
}

}  // namespace

int line_of(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

std::string text_of(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "";
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  std::string text = out.c_str();
  if (text.size() > kMaxValueText) text = text.substr(0, kMaxValueText - 3) + "...";
  return text;
}

std::string read_scalar(const YAML::Node& node, const Where& where) {
  if (!node.IsScalar()) throw_input("expected a single value, got " + kind_of(node), where);
  if (node.Scalar().empty()) throw_input("expected a value, got an empty string", where);
  return node.Scalar();
}

double read_quantity(const YAML::Node& node, const Where& where, Dimension dim) {
  const std::string text = read_scalar(node, where);
  try {
    return parse_quantity(text, dim);
  } catch (const Error& e) {
    throw e.within(where);
  }
}

MapReader::MapReader(const YAML::Node& node, Where where) : node_(node), where_(std::move(where)) {
  if (!node.IsMap()) {
    Where w = where_;
    w.value = text_of(node);
    if (w.line == 0) w.line = line_of(node);
    throw_input("expected a map of keys, got " + kind_of(node), w);
  }
}

void MapReader::allow_only(const std::vector<std::string>& allowed) const {
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    // A list or a map written as a key ("? [a, b]") is no key name: quote it as written.
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : text_of(entry.first);
    Where w{where_.file, path(key), text_of(entry.second), line_of(entry.first)};
    if (!seen.insert(key).second) throw_input("key given twice", w);
    bool known = false;
    for (const auto& a : allowed) known = known || a == key;
    if (!known) {
      throw_input("unknown key '" + value_excerpt(key) + "'" + did_you_mean(key, allowed) +
                      "; allowed in " +
                      (where_.key.empty() ? "the case file" : "'" + where_.key + "'") + ": " +
                      join(allowed),
                  w);
    }
  }
}

bool MapReader::has(const std::string& key) const {
  for (const auto& entry : node_)
    if (entry.first.Scalar() == key) return true;
  return false;
}

YAML::Node MapReader::at(const std::string& key) const {
  for (const auto& entry : node_)
    if (entry.first.Scalar() == key) return entry.second;
  throw_input("missing key '" + value_excerpt(key) + "'", where(key));
}

std::string MapReader::path(const std::string& key) const {
  return where_.key.empty() ? key : where_.key + "." + key;
}

Where MapReader::where(const std::string& key) const {
  for (const auto& entry : node_) {
    if (entry.first.Scalar() == key)
      return Where{where_.file, path(key), text_of(entry.second), line_of(entry.first)};
  }
  return Where{where_.file, path(key), "", where_.line};
}

std::string MapReader::scalar(const std::string& key) const {
  return read_scalar(at(key), where(key));
}

std::string MapReader::scalar_or(const std::string& key, const std::string& fallback) const {
  return has(key) ? scalar(key) : fallback;
}

double MapReader::quantity(const std::string& key, Dimension dim) const {
  return read_quantity(at(key), where(key), dim);
}

double MapReader::quantity_or(const std::string& key, Dimension dim, double fallback) const {
  return has(key) ? quantity(key, dim) : fallback;
}

double MapReader::positive(const std::string& key, Dimension dim) const {
  const double value = quantity(key, dim);
  if (!(value > 0.0)) throw_input("must be positive", where(key));
  if (dim == Dimension::kLength) check_plausible(value, kLengthRange, where(key));
  if (dim == Dimension::kForce) check_plausible(value, kForceRange, where(key));
  if (dim == Dimension::kStress) check_plausible(value, kPressureRange, where(key));
  return value;
}

double MapReader::positive_or(const std::string& key, Dimension dim, double fallback) const {
  return has(key) ? positive(key, dim) : fallback;
}

int MapReader::integer_or(const std::string& key, int fallback) const {
  if (!has(key)) return fallback;
  const std::string text = scalar(key);
  int value = 0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (status != std::errc() || end != text.data() + text.size())
    throw_input("expected a whole number", where(key));
  return value;
}

size_t read_choice_index(const YAML::Node& node, const Where& where,
                         const std::vector<std::string>& names) {
  const std::string text = read_scalar(node, where);
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == text) return i;
  throw_input("unknown value" + did_you_mean(text, names) + "; allowed: " + join(names), where);
}

std::vector<std::string> read_name_list(const MapReader& map, const std::string& key) {
  const YAML::Node list = map.at(key);
  const Where list_where = map.where(key);
  if (!list.IsSequence() || list.size() == 0)
    throw_input("expected a non-empty list of names such as [tip, apex]", list_where);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Where w{list_where.file, list_where.key + "[" + std::to_string(i) + "]", text_of(list[i]),
                  line_of(list[i])};
    if (!list[i].IsScalar() || list[i].Scalar().empty()) throw_input("expected a name", w);
    if (std::find(names.begin(), names.end(), list[i].Scalar()) != names.end())
      throw_input("listed twice", w);
    names.push_back(list[i].Scalar());
  }
  return names;
}

}  // namespace si
