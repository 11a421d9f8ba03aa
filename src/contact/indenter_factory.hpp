// Builds the indenter a spec asks for (indenter_spec.hpp) at a pose.
#pragma once

#include <memory>

#include "contact/indenter.hpp"
#include "contact/indenter_spec.hpp"

namespace si {

// Throws an input Error naming `indenter.<key>` for invalid values or combinations (a
// non-positive radius, an edge radius outside [0, radius), exponents outside (0, 2], a zero
// direction of travel, a cylinder axis parallel to the direction).
std::unique_ptr<Indenter> make_indenter(const IndenterSpec& spec, const IndenterPose& pose);

}  // namespace si
