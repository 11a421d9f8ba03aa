// The shell's mid-surface geometry and edge support, as a case file gives them
// (docs/case-file.md `shell`; read by io/case_file.hpp, built into a mesh by shell_model.hpp).
#pragma once

#include <vector>

#include "model/named_supports.hpp"

namespace si {

enum class ShellType { kSphericalCap, kFlatCircularPlate, kRectangularPlate, kCylindricalPanel };
enum class EdgeCondition { kClamped, kHinged, kSimplySupported, kFree };

// Geometry of the shell mid-surface; which lengths are used depends on `type`.
struct ShellSpec {
  ShellType type = ShellType::kSphericalCap;
  double base_radius = 25.0;  // mm, spherical cap: radius of the base circle (plan view)
  double radius = 80.9;       // mm, cap: sphere radius; flat plate: plate radius;
                              //     cylindrical panel: cylinder radius
  double length_x = 0;        // mm, rectangular plate
  double length_y = 0;        // mm, rectangular plate
  double length = 0;          // mm, cylindrical panel: axial length
  double angle_deg = 0;       // cylindrical panel: opening angle
  EdgeCondition edge = EdgeCondition::kClamped;  // the default for every edge `supports` omits
  std::vector<NamedSupportSpec> supports;        // top-level `supports:`, on named sets
};

}  // namespace si
