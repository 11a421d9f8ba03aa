#include "io/study_file.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/decimal_number.hpp"
#include "core/value_excerpt.hpp"
#include "io/yaml_reader.hpp"

namespace si {
namespace {

std::string read_text(const std::string& path, const Where& where, const std::string& what) {
  std::ifstream in(path);
  if (!std::filesystem::is_regular_file(path) || !in)
    throw_input("cannot open the " + what + " (does it exist?)", where);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

YAML::Node load_yaml(const std::string& text, const std::string& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw_input("not valid YAML: " + e.msg, Where{file, "", "", e.mark.line + 1});
  }
}

std::vector<std::string> split_key(const std::string& key, const Where& where) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '.')) {
    if (part.empty()) throw_input("empty part in the dotted key", where);
    parts.push_back(part);
  }
  if (parts.empty() || key.back() == '.') throw_input("empty part in the dotted key", where);
  return parts;
}

// Keys with their values, in file order; a value that is not a map is refused, and so is a key
// that is not a dotted key (a list or a map written as a key).
std::vector<KeyValue> read_key_values(const MapReader& map, const std::string& key) {
  std::vector<KeyValue> out;
  if (!map.has(key)) return out;
  const MapReader sub(map.at(key), map.where(key));
  for (const auto& kv : sub.node()) {
    if (!kv.first.IsScalar() || kv.first.Scalar().empty())
      throw_input("expected a dotted case-file key such as mesh.size_apex, got " +
                      std::string(kv.first.IsSequence() ? "a list" : "a map or nothing"),
                  Where{map.where().file, key, text_of(kv.first), line_of(kv.first)});
    out.push_back({kv.first.Scalar(), kv.second});
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<YAML::Node>>> read_vary(const MapReader& map) {
  std::vector<std::pair<std::string, std::vector<YAML::Node>>> vary;
  for (const KeyValue& kv : read_key_values(map, "vary")) {
    const Where where{map.where().file, "vary." + kv.key, text_of(kv.value), line_of(kv.value)};
    if (!kv.value.IsSequence() || kv.value.size() == 0)
      throw_input("expected a non-empty list of values", where);
    std::vector<YAML::Node> values(kv.value.begin(), kv.value.end());
    vary.emplace_back(kv.key, values);
  }
  if (vary.empty()) throw_input("nothing to vary: `vary:` needs at least one key", map.where());
  return vary;
}

// fit: {model: power, range: "a:b"}; the range bounds are depths in mm.
StudyFit read_fit(const MapReader& map) {
  const MapReader f(map.at("fit"), map.where("fit"));
  f.allow_only({"model", "range"});
  StudyFit fit;
  fit.model = f.scalar_or("model", "power");
  if (fit.model != "power")
    throw_input("unknown fit model (allowed: power, y = C1 x^C2)", f.where("model"));
  if (!f.has("range")) return fit;
  const std::string r = f.scalar("range");
  const auto colon = r.find(':');
  if (colon == std::string::npos) throw_input("expected a:b, a: or :b", f.where("range"));
  const std::string a = r.substr(0, colon);
  const std::string b = r.substr(colon + 1);
  const std::optional<double> lo = parse_decimal(a), hi = parse_decimal(b);
  if ((!a.empty() && !lo) || (!b.empty() && !hi))
    throw_input("not a finite decimal number; expected a:b, a: or :b (depths in mm)",
                f.where("range"));
  if (lo) fit.depth_min = *lo;
  if (hi) fit.depth_max = *hi;
  if (fit.depth_min >= fit.depth_max)
    throw_input("the lower end is not below the upper end", f.where("range"));
  return fit;
}

// "[15/-15]2S" -> "15_-15_2S": letters, digits, '-' and '.' kept, runs of others become '_'.
std::string slug_of(const std::vector<std::pair<std::string, std::string>>& values) {
  std::string s;
  for (const auto& v : values) {
    for (char c : v.second) {
      const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.';
      if (keep)
        s += c;
      else if (!s.empty() && s.back() != '_')
        s += '_';
    }
    if (!s.empty() && s.back() != '_') s += '_';
  }
  while (!s.empty() && s.back() == '_') s.pop_back();
  return s.substr(0, 60);
}

// The most cases a study may expand to: every case is a full run, so more is a slip (8 keys of
// 25 values asked for 1.5e11 cases and allocated until bad_alloc). Counted before expanding.
constexpr double kMaxCases = 10000;

void check_case_count(const StudyFile& study) {
  if (study.zip) return;  // zip: as many cases as the longest list, which the file holds
  double count = 1;
  std::string product;
  for (const auto& [key, values] : study.vary) {
    count *= static_cast<double>(values.size());
    product += (product.empty() ? "" : " x ") + key + " (" + std::to_string(values.size()) + ")";
  }
  if (count <= kMaxCases) return;
  char total[32];
  std::snprintf(total, sizeof total, "%.4g", count);
  throw_input("the product of the varied values is " + std::string(total) + " cases (" + product +
                  "), more than " + std::to_string(static_cast<long>(kMaxCases)) +
                  "; vary fewer keys or values, or use combine: zip",
              Where{study.file, "vary", "", line_of(study.vary.front().second.front())});
}

// The index tuples of the cases: the product (first key slowest) or the zip of the lists.
std::vector<std::vector<size_t>> combinations(const StudyFile& study) {
  std::vector<std::vector<size_t>> out;
  if (study.zip) {
    const size_t n = study.vary.front().second.size();
    for (const auto& [key, values] : study.vary)
      if (values.size() != n)
        throw_input("combine: zip needs lists of equal length (" + study.vary.front().first +
                        " has " + std::to_string(n) + " values, this one " +
                        std::to_string(values.size()) + ")",
                    Where{study.file, "vary." + key, "", line_of(values.front())});
    for (size_t i = 0; i < n; ++i) out.emplace_back(study.vary.size(), i);
    return out;
  }
  out.emplace_back();
  for (const auto& kv : study.vary) {
    std::vector<std::vector<size_t>> next;
    for (const auto& prefix : out)
      for (size_t i = 0; i < kv.second.size(); ++i) {
        next.push_back(prefix);
        next.back().push_back(i);
      }
    out = std::move(next);
  }
  return out;
}

}  // namespace

void set_dotted_key(YAML::Node root, const std::string& dotted_key, const YAML::Node& value,
                    const Where& where) {
  const std::vector<std::string> parts = split_key(dotted_key, where);
  // yaml-cpp's Node::operator= assigns content, so each level is a freshly constructed handle.
  std::vector<YAML::Node> chain{root};
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node parent = chain.back();
    if (!parent[parts[i]] || parent[parts[i]].IsNull())
      parent[parts[i]] = YAML::Node(YAML::NodeType::Map);
    YAML::Node child = parent[parts[i]];
    if (!child.IsMap())
      throw_input("cannot set this key: '" + value_excerpt(parts[i]) +
                      "' in the base case is not a map (it is '" + text_of(child) + "')",
                  where);
    chain.push_back(child);
  }
  YAML::Node last = chain.back();
  last[parts.back()] = YAML::Clone(value);
}

StudyFile parse_study_file(const std::string& yaml_text, const std::string& file_label,
                           const std::string& base_dir) {
  const YAML::Node root = load_yaml(yaml_text, file_label);
  const MapReader map(root, Where{file_label, "", "", 0});
  map.allow_only({"name", "base", "vary", "combine", "quick", "fit"});
  StudyFile s;
  s.file = file_label;
  s.name = map.scalar_or("name", std::filesystem::path(file_label).stem().string());
  const std::filesystem::path base = map.scalar("base");
  s.base = (base.is_absolute() ? base : std::filesystem::path(base_dir) / base).string();
  s.base_yaml = read_text(s.base, map.where("base"), "base case file");
  s.vary = read_vary(map);
  s.zip = map.choice_or("combine", Choices<bool>{{"product", false}, {"zip", true}}, false);
  check_case_count(s);
  s.quick = read_key_values(map, "quick");
  s.has_fit = map.has("fit");
  if (s.has_fit) s.fit = read_fit(map);
  return s;
}

StudyFile read_study_file(const std::string& path) {
  const std::string text = read_text(path, Where{path, "", "", 0}, "study file");
  return parse_study_file(text, path, std::filesystem::path(path).parent_path().string());
}

std::vector<StudyCase> expand_study(const StudyFile& study, bool quick) {
  const YAML::Node base = load_yaml(study.base_yaml, study.base);
  if (!base.IsMap())
    throw_input("the base case file is not a YAML map", Where{study.base, "", "", 0});
  std::vector<StudyCase> cases;
  for (const std::vector<size_t>& pick : combinations(study)) {
    const int index = static_cast<int>(cases.size()) + 1;
    std::vector<std::pair<std::string, std::string>> chosen;  // every varied key's value
    YAML::Node node = YAML::Clone(base);
    std::string described;
    std::vector<std::pair<std::string, std::string>> varying;  // keys with more than one value
    for (size_t k = 0; k < pick.size(); ++k) {
      const auto& [key, values] = study.vary[k];
      const YAML::Node& v = values[pick[k]];
      set_dotted_key(node, key, v, Where{study.file, "vary." + key, text_of(v), line_of(v)});
      chosen.emplace_back(key, text_of(v));
      if (values.size() == 1) continue;
      varying.emplace_back(key, text_of(v));
      described += (described.empty() ? "" : ", ") + key + " = " + text_of(v);
    }
    if (quick)  // last: a smoke test overrides the varied keys too (e.g. a coarser mesh)
      for (const KeyValue& kv : study.quick) {
        set_dotted_key(node, kv.key, kv.value,
                       Where{study.file, "quick." + kv.key, text_of(kv.value), line_of(kv.value)});
        for (auto& [key, value] : chosen)
          if (key == kv.key) value = text_of(kv.value);  // the table shows what was run
      }
    char number[16];
    std::snprintf(number, sizeof number, "%03d", index);
    const std::string label = study.file + " case " + std::to_string(index) +
                              (described.empty() ? "" : " (" + described + ")");
    YAML::Emitter emitter;
    emitter << node;
    const std::string yaml = "# " + label + (quick ? ", --quick" : "") + "; base " + study.base +
                             "\n" + emitter.c_str() + "\n";
    cases.push_back(StudyCase{index, chosen, label,
                              std::string(number) + (varying.empty() ? "" : "_" + slug_of(varying)),
                              yaml, parse_case_file(yaml, label)});
  }
  return cases;
}

}  // namespace si
