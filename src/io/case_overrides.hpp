// The numbers of a case file that may be set from outside it - a calibration's parameters
// (`shellindent calibrate --param KEY=LO:HI`, docs/calibration.md) - named by their dotted
// case-file keys, and the case with such numbers set. The setting happens on the YAML, as a
// sweep's does (io/study_file.hpp set_dotted_key), so every case built this way goes through the
// case-file reader and its validation.
//
// The keys: the elastic constants of the top-level `material`, of each entry of `materials`
// and of `indenter.material` (E1 E2 E3 G12 G13 G23 nu12 nu13 nu23 for an orthotropic material,
// E nu for an isotropic one), and `laminate.ply_thickness`. A library material has them too
// (the library's values); setting one first writes the material out as its inline table under
// its library name, so that plies naming it still find it.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "core/units.hpp"

namespace si {

struct NumericKey {
  std::string key;      // "material.E3"
  Dimension dimension;  // of its value: stress, length, dimensionless
  double value = 0;     // in the case (internal units: MPa, mm)
};

// The keys of a case (the YAML of a valid case file, read from `file`).
std::vector<NumericKey> numeric_keys(const YAML::Node& case_root, const std::string& file);

// The key named `name`; an input error at `where` with a did-you-mean and the list otherwise.
const NumericKey& find_numeric_key(const std::vector<NumericKey>& keys, const std::string& name,
                                   const Where& where);

struct NumericValue {
  std::string key;
  Dimension dimension;
  double value = 0;  // internal units
};

// A copy of `case_root` with each key set to its value, written with the internal unit.
YAML::Node with_numeric_values(const YAML::Node& case_root, const std::vector<NumericValue>& values,
                               const std::string& file);

}  // namespace si
