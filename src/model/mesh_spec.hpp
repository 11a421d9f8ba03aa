// How the shell is meshed (docs/case-file.md `mesh`; shell_model.hpp builds it).
#pragma once

#include "model/symmetry.hpp"
#include "shell/shell_element.hpp"

namespace si {

// Mesh size grades from size_apex at the indentation point to size_edge beyond refine_radius.
struct MeshSpec {
  ElementType element = ElementType::kMitc4;
  double size_apex = 0.5;       // mm
  double size_edge = 2.0;       // mm
  double refine_radius = 13.0;  // mm, measured from the indentation point in plan
  Symmetry symmetry = Symmetry::kFull;
};

}  // namespace si
