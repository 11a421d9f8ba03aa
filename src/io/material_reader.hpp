// Materials in case files: a library name ("paper-carbon-epoxy") or an inline table of constants
// with units. Shared by the case-file reader and the CLI.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "material/material.hpp"

namespace si {

// Reads `node`, found at `context` (file, dotted key, line):
//   a string                     -> the library material of that name;
//   {type: orthotropic, E1, E2, E3, G12, G13, G23 (stresses), nu12, nu13, nu23, name?}
//   {type: isotropic, E (stress), nu, name?}
// An inline material without `name` is named after the last part of context.key. Errors from
// Material's validation are reported at the offending constant ("materials.foam.nu").
Material read_material(const YAML::Node& node, const Where& context);

// The `materials:` section: a map name -> (library name or inline table). Each material is named
// by its key, so that "face: paper-carbon-epoxy" defines a material "face".
std::vector<Material> read_material_map(const YAML::Node& node, const Where& context);

// The materials a case file can refer to by name in its laminate section.
struct MaterialTable {
  Material default_material;    // the top-level `material:`
  std::vector<Material> named;  // the `materials:` section, in file order

  // `named` first, then the default material's name, then the library. Throws an input error
  // at `where` listing what is defined when the name is unknown.
  Material find(const std::string& name, const Where& where) const;
};

}  // namespace si
