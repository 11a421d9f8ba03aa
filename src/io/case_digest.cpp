#include "io/case_digest.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "core/value_excerpt.hpp"

namespace si {
namespace {

using Entries = std::vector<std::pair<std::string, std::string>>;

void flatten(const YAML::Node& node, const std::string& key, Entries& out) {
  if (node.IsMap()) {
    for (const auto& kv : node) {
      const std::string name = kv.first.Scalar();
      if (key.empty() && name == "output") continue;
      flatten(kv.second, key.empty() ? name : key + "." + name, out);
    }
  } else if (node.IsSequence()) {
    if (node.size() == 0) out.emplace_back(key, "[]");
    for (std::size_t i = 0; i < node.size(); ++i)
      flatten(node[i], key + "[" + std::to_string(i) + "]", out);
  } else {
    out.emplace_back(key, node.IsNull() ? "" : node.Scalar());
  }
}

// FNV-1a, 64 bit: a fingerprint for telling cases apart at a glance, not a security measure.
std::string fnv1a(const Entries& entries) {
  std::uint64_t h = 14695981039346656037ull;
  const auto mix = [&h](const std::string& s) {
    for (unsigned char c : s) {
      h ^= c;
      h *= 1099511628211ull;
    }
    h ^= 0xFF;  // separator: ("ab", "c") and ("a", "bc") differ
    h *= 1099511628211ull;
  };
  for (const auto& [k, v] : entries) {
    mix(k);
    mix(v);
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace

nlohmann::json CaseDigest::to_json() const {
  nlohmann::json e = nlohmann::json::object();
  for (const auto& [k, v] : entries) e[k] = v;
  return {{"digest", digest}, {"entries", e}};
}

CaseDigest CaseDigest::from_json(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("digest") || !j.contains("entries") ||
      !j["entries"].is_object())
    throw std::invalid_argument("not a case digest");
  CaseDigest d;
  d.digest = j["digest"].get<std::string>();
  for (const auto& [k, v] : j["entries"].items()) d.entries.emplace_back(k, v.get<std::string>());
  std::sort(d.entries.begin(), d.entries.end());
  return d;
}

CaseDigest case_digest(const std::string& yaml_text) {
  CaseDigest d;
  flatten(YAML::Load(yaml_text), "", d.entries);
  std::sort(d.entries.begin(), d.entries.end());
  d.digest = fnv1a(d.entries);
  return d;
}

std::vector<std::string> case_differences(const CaseDigest& now, const CaseDigest& before,
                                          std::string& first_key, std::size_t limit) {
  std::vector<std::string> out;
  first_key.clear();
  if (now.digest == before.digest && now.entries == before.entries) return out;
  const std::map<std::string, std::string> a(now.entries.begin(), now.entries.end());
  const std::map<std::string, std::string> b(before.entries.begin(), before.entries.end());
  std::vector<std::string> keys;
  for (const auto& kv : a) keys.push_back(kv.first);
  for (const auto& kv : b)
    if (!a.count(kv.first)) keys.push_back(kv.first);
  std::sort(keys.begin(), keys.end());
  std::size_t count = 0;
  for (const std::string& k : keys) {
    const auto x = a.find(k), y = b.find(k);
    if (x != a.end() && y != b.end() && x->second == y->second) continue;
    if (first_key.empty()) first_key = k;
    if (++count > limit) continue;
    const std::string here =
        x == a.end() ? "absent here" : "'" + value_excerpt(x->second) + "' here";
    const std::string there = y == b.end() ? "absent in the checkpoint"
                                           : "'" + value_excerpt(y->second) + "' in the checkpoint";
    out.push_back(k + " is " + here + " but " + there);
  }
  if (count > limit) out.push_back("and " + std::to_string(count - limit) + " more");
  return out;
}

}  // namespace si
