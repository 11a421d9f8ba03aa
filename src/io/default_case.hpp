// The built-in default case of `shellindent run` and of the Python module's default_case(): the
// source paper's clamped carbon/epoxy cap, [0/0]2S (specially orthotropic, so a quarter model is
// exact), 12.7 mm sphere on the outer face, nonlinear, 0 to 10 mm by pseudo-arclength with
// 0.1 mm steps (docs/case-file.md).
#pragma once

#include <string>

namespace si {

// The case file's text; its label in messages is kDefaultCaseLabel.
std::string default_case_yaml();
inline constexpr const char* kDefaultCaseLabel = "built-in default case";

}  // namespace si
