// The one case-file schema of shellindent (docs/case-file.md): a YAML file describing the
// laminate, the shell, the mesh, the indenter, contact, the load path and the output. Reading
// converts every quantity to internal units (mm, MPa, N, deg) and validates it, so the solvers
// downstream receive only values they can use. Defaults of the optional sections are the source
// paper's case: a clamped spherical cap (base radius 25 mm, R = 80.9 mm) indented by a 12.7 mm
// rigid sphere on its outer face, geometrically nonlinear, to 10 mm depth by pseudo-arclength.
#pragma once

#include <string>
#include <vector>

#include "analysis/indentation_case.hpp"
#include "analysis/static_spec.hpp"
#include "io/output_reader.hpp"
#include "material/material.hpp"

namespace si {

// The specs of the rooms that use them, filled here: the shell model's (model/shell_model.hpp:
// laminate, shell, mesh, kinematics, load), the indenter's (contact/indenter_spec.hpp), the
// contact's and the path's (analysis/). What only the command line uses stays here.

struct CaseFile : IndentationCase {
  Material material;  // the top-level `material:`, the default ply material
  OutputSpec output;
  // `static:` (shellindent static): the method and its steps; load.steps, the recorded nodes
  // and the solver are the command's.
  StaticSettings static_run;
  // static.record: node sets whose mean displacement static.csv and static.json carry.
  std::vector<std::string> static_record;
};

// Reads and validates a case file. Every error is an input si::Error naming the file and, where
// they exist, the dotted key, the value as written and the 1-based line (a missing file or an
// empty one has no key or line; a missing key has no value).
CaseFile read_case_file(const std::string& path);

// As read_case_file, from text; `file_label` stands for the file name in messages.
CaseFile parse_case_file(const std::string& yaml_text, const std::string& file_label);

}  // namespace si
