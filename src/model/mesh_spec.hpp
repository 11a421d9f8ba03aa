// How the shell is meshed (docs/case-file.md `mesh`; shell_model.hpp builds it).
#pragma once

#include <optional>
#include <string>

#include "model/symmetry.hpp"
#include "shell/shell_element.hpp"

namespace si {

// How a run states its discretisation error (docs/theory/discretisation-error.md): the
// Zienkiewicz-Zhu estimate of every point's energy-norm error (always), and with kCompanion also
// the force's, from a second run on the mesh with twice the element sizes
// (analysis/companion_mesh.hpp).
enum class ErrorEstimate { kRecovery, kCompanion };

// The refined zone's radius without an indenter to size it from (load-controlled runs).
constexpr double kDefaultRefineRadius = 13.0;  // mm

// Mesh size grades from size_apex at the indentation point to size_edge beyond refine_radius.
struct MeshSpec {
  ElementType element = ElementType::kMitc4;
  double size_apex = 0.5;  // mm
  double size_edge = 2.0;  // mm
  // mm, measured from the indentation point in plan. None: the indenter's reach at depth_max
  // (analysis/refine_zone.hpp sets it before the mesh is built), else kDefaultRefineRadius.
  std::optional<double> refine_radius;
  // The largest estimated discretisation error the user accepts (relative: the force's with
  // kCompanion, else the energy norm's, IndentationState::error_estimate); a run above it warns.
  // 0: no tolerance.
  double tolerance = 0;
  ErrorEstimate error_estimate = ErrorEstimate::kRecovery;
  Symmetry symmetry = Symmetry::kFull;
  // Rectangular plates and cylindrical panels: graded like the cap (size_apex within
  // refine_radius, growing to size_edge) instead of uniform at size_apex.
  bool graded = false;
  // Rectangular plates: mesh lines at x = +-line_x and y = +-line_y (0: none), a station moved or
  // inserted there (model/fixture.hpp with_station); a fixture puts them on its cut-out's edges.
  double line_x = 0;  // mm
  double line_y = 0;  // mm
  // A mesh from a Gmsh file (path resolved against the case file's directory; empty: the
  // built-in mesh of `shell`), with the reader's options (model/gmsh_reader.hpp).
  std::string file;
  bool reorient = false;
  bool flip = false;
};

inline double refine_radius_or_default(const MeshSpec& m) {
  return m.refine_radius.value_or(kDefaultRefineRadius);
}

}  // namespace si
