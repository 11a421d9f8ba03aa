// A fraction in a case file (path.nonlinearity_fraction): a plain number or per cent.
#pragma once

#include <string>

#include "core/error.hpp"
#include "io/yaml_reader.hpp"

namespace si {

// In (0, 1), written 0.05 or 5 %; an input error at `where` otherwise.
double read_fraction(const std::string& text, const Where& where);
// The key's fraction in `map`, or `fallback` without the key.
double fraction_or(const MapReader& map, const std::string& key, double fallback);

}  // namespace si
