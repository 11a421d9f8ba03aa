// The `path` section of a case file (docs/case-file.md): the depth path's method, steps, depths,
// stability, nonlinearity fraction and geometric imperfection.
#pragma once

#include "analysis/contact_spec.hpp"
#include "analysis/path_spec.hpp"
#include "io/yaml_reader.hpp"

namespace si {

// The optional `path` section of `top` (defaults without it). The contact section decides
// whether `stability` is allowed (not with a local contact law).
PathSpec read_path(const MapReader& top, const ContactSpec& contact);

}  // namespace si
