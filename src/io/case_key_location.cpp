#include "io/case_key_location.hpp"

#include <sstream>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "io/yaml_reader.hpp"

namespace si {
namespace {

// "laminate.plies[2].thickness" -> laminate, plies, [2], thickness.
std::vector<std::string> key_parts(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : key) {
    if (c == '.' || c == '[') {
      if (!part.empty()) parts.push_back(part);
      part = c == '[' ? "[" : "";
    } else if (c == ']') {
      parts.push_back(part + "]");
      part.clear();
    } else {
      part += c;
    }
  }
  if (!part.empty()) parts.push_back(part);
  return parts;
}

}  // namespace

Error located_in_case(const Error& e, const std::string& yaml_text) {
  const Where& w = e.where();
  if (w.line > 0 || w.key.empty()) return e;
  YAML::Node node;
  try {
    node = YAML::Load(yaml_text);
  } catch (const YAML::Exception&) {
    return e;
  }
  int line = 0;
  for (const std::string& part : key_parts(w.key)) {
    if (part.front() == '[') {
      std::size_t i = 0;
      if (!node.IsSequence() || !(std::istringstream(part.substr(1)) >> i) || i >= node.size())
        return e;
      const YAML::Node child = node[i];
      node.reset(child);  // operator= would assign the child's content into the tree
      line = line_of(node);
      continue;
    }
    if (!node.IsMap()) return e;
    YAML::Node child;
    bool found = false;
    for (const auto& kv : node)
      if (kv.first.IsScalar() && kv.first.Scalar() == part) {
        line = line_of(kv.first);
        child.reset(kv.second);
        found = true;
        break;
      }
    if (!found) return e;
    node.reset(child);
  }
  Where located = w;
  located.line = line;
  if (node.IsScalar() || node.IsSequence()) located.value = text_of(node);
  return Error(e.kind(), e.reason(), located);
}

}  // namespace si
