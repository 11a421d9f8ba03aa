// Errors found after a case file was read (mesh generation, the model's set-up, the indenter's
// placement) know the dotted key but neither its line nor the value as written: the model works
// in internal numbers ("80.900000"). This puts both back from the case file's text, so that every
// error a user sees reads like a reader's error: "case.yaml:5: shell.radius = '80.9 mm': ...".
#pragma once

#include <string>

#include "core/error.hpp"

namespace si {

// `e` with its line (and, for a scalar or a list, its value as written) taken from `yaml_text`
// when `e` names a dotted key of that text and has no line yet; `e` unchanged otherwise (a key
// the file does not contain, whose default applied, has no line to point at).
Error located_in_case(const Error& e, const std::string& yaml_text);

}  // namespace si
