// The `laminate:` section of a case file, in either of its two forms:
//   {layup: "[45/-45]2S", ply_thickness: 0.475 mm, material: name?, reference: mid}
//   {plies: [ {material: name?, thickness: q, angle: q?}
//             | {layup: "...", ply_thickness: q, material: name?} ... ], reference: mid}
// Plies are listed bottom first (x3 = -h/2 upwards; the top face is the outer, contact face).
// reference: mid | bottom | top | <length above the mid-surface>.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "core/error.hpp"
#include "io/material_reader.hpp"
#include "section/laminate.hpp"

namespace si {

// Builds and validates the laminate found at `context` (file, key "laminate", line).
Laminate read_laminate(const YAML::Node& node, const Where& context,
                       const MaterialTable& materials);

// The reference-surface offset above the mid-surface (mm) named by `text` for a laminate of
// thickness h: mid, bottom, top or a length. Throws an input si::Error without location (the
// caller adds the file/option and key) if the text is none of these or lies outside the laminate.
double parse_reference_surface(const std::string& text, double h);

}  // namespace si
