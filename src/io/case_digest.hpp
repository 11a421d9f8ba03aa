// What makes two case files the same case for `run --resume`: every key and value except the
// `output` section (where and how results are written does not change the path), as written,
// in a canonical order. A checkpoint keeps this flat list and its digest; a resume with a case
// that differs is refused, naming the keys that differ (a [0/90]2S checkpoint resumed with a
// [0/0]2S case file once continued the path of one laminate under the name of the other).
//
// The comparison is textual: "0.475 mm" and "0.000475 m" differ, and so do a default left out
// and the same default written. Refusing those errs on the safe side; the message says what
// differs.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace si {

struct CaseDigest {
  // "laminate.layup" -> "[0/90]2S", "indenter.position[2]" -> "40 mm", sorted by key.
  std::vector<std::pair<std::string, std::string>> entries;
  std::string digest;  // 16 hex digits, FNV-1a of the entries

  nlohmann::json to_json() const;
  // Throws std::invalid_argument if `j` is not what to_json() writes.
  static CaseDigest from_json(const nlohmann::json& j);
};

// The case's entries without `output`. `yaml_text` must be a case file the reader accepted.
CaseDigest case_digest(const std::string& yaml_text);

// The differences of `now` against `before`, at most `limit`, e.g.
// "laminate.layup is '[0/0]2S' here but '[0/90]2S' in the checkpoint"; the first key that
// differs goes to `first_key`. Empty when the digests agree.
std::vector<std::string> case_differences(const CaseDigest& now, const CaseDigest& before,
                                          std::string& first_key, std::size_t limit = 3);

}  // namespace si
