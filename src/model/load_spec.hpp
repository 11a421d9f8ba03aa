// The load of a load-controlled run (`shellindent static`, docs/case-file.md `load`).
#pragma once

#include <vector>

#include "model/named_loads.hpp"

namespace si {

// kNone: no apex force or uniform pressure, only the named `loads`.
enum class LoadType { kApexForce, kPressure, kNone };

// The load grows from 0 to its full value in `steps` equal increments. No contact: the
// indenter, contact and path sections are not used.
struct LoadSpec {
  LoadType type = LoadType::kApexForce;
  double force = 0;       // N, apex_force: total force along -z at the apex node (the whole shell;
                          //    a quarter model carries a quarter of it)
  double pressure = 0;    // MPa, pressure: on every element, acting against the director (inwards
                          //    on the cap's convex side, i.e. towards -z at the apex)
  int steps = 10;         // >= 1
  bool follower = false;  // pressure only: follows the deformed surface
  std::vector<NamedLoadSpec> named;  // top-level `loads:`, on named sets
};

}  // namespace si
