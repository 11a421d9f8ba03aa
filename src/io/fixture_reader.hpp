// Reading a case file's `fixture` section (docs/case-file.md): a test fixture preset (ASTM D7136,
// D6264 edge-supported or rigidly backed) into model/fixture_spec.hpp's FixtureSpec, and what the
// preset sets of the plate: a rectangular 150 x 100 mm plate unless `shell` gives its size (or a
// mesh file its geometry) and free edges (the plate rests on the frame); the case file's reader
// makes its mesh graded unless `mesh.grading` says otherwise.
#pragma once

#include "io/yaml_reader.hpp"
#include "model/fixture_spec.hpp"
#include "model/shell_spec.hpp"

namespace si {

// No `fixture` key: type kNone and the shell untouched. Errors name the file, line, key and
// value: an unknown type, a key the type does not take (window for D6264, ...), a missing
// opening_diameter, a window or clamp that is not a list of two lengths, a `shell` that is not a
// rectangular plate or whose `edge` is not free.
FixtureSpec read_fixture(const MapReader& top, ShellSpec& shell);

}  // namespace si
