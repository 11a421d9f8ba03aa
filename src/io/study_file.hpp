// A parameter study (`shellindent sweep`, docs/sweeps.md): a base case file and the case-file
// keys to vary. The variation happens on the YAML text: each case is the base YAML with the
// dotted keys set to the study's values, emitted and read by the case-file reader
// (io/case_file.hpp), so every case gets the reader's validation and error messages, labelled
// "STUDY case K (key = value, ...)". All cases are built and checked before anything runs.
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "io/case_file.hpp"

namespace si {

// The optional `fit:` of a study: the contact law T = C1 h^C2 fitted to each case's path.
struct StudyFit {
  std::string model = "power";  // the only model so far: y = C1 x^C2 in linear space
  double depth_min = 0;         // mm, the fit uses points with depth in (depth_min, depth_max]
  double depth_max = std::numeric_limits<double>::infinity();
};

// One dotted key with its value as YAML (a scalar, list or map node).
struct KeyValue {
  std::string key;
  YAML::Node value;
};

struct StudyFile {
  std::string file;       // the study file (or label)
  std::string name;       // `name:`, default: the study file's stem
  std::string base;       // the base case file, resolved against the study file's directory
  std::string base_yaml;  // its text
  std::vector<std::pair<std::string, std::vector<YAML::Node>>> vary;  // in file order
  bool zip = false;                                                   // combine: zip (else product)
  std::vector<KeyValue> quick;  // applied with --quick, after the varied keys
  bool has_fit = false;
  StudyFit fit;
};

// One case of a study: its values, label, directory name and generated case text.
struct StudyCase {
  int index = 0;                                            // 1-based
  std::vector<std::pair<std::string, std::string>> values;  // varied key -> value as written
  std::string label;   // "paper_layups.yaml case 3 (laminate.layup = [15/-15]2S)"
  std::string slug;    // "003_15_-15_2S": the case's directory under DIR/cases/
  std::string yaml;    // the generated case file
  CaseFile case_file;  // as the case-file reader read `yaml`
};

// Reads and validates a study file; every error is an input si::Error naming the file and key.
StudyFile read_study_file(const std::string& path);

// As read_study_file from text; `base_dir` resolves the relative `base:`.
StudyFile parse_study_file(const std::string& yaml_text, const std::string& file_label,
                           const std::string& base_dir);

// Sets `dotted_key` ("mesh.size_apex") in the map `root` to `value`, creating missing maps on the
// way. Throws an input error at `where` if a part of the key on the way is not a map.
void set_dotted_key(YAML::Node root, const std::string& dotted_key, const YAML::Node& value,
                    const Where& where);

// The cases of a study: the product (or zip) of the varied values, first key slowest. Each case is
// the base with the varied keys and then the quick keys (if `quick`) set, read back by the
// case-file reader; an unknown or bad key is an input error naming the study and the key.
std::vector<StudyCase> expand_study(const StudyFile& study, bool quick);

}  // namespace si
