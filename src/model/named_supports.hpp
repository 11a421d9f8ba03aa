// Supports on named node sets, as a user writes them (docs/case-file.md, `supports`), and
// their translation into Support and PrescribedDisplacement (supports.hpp).
//
// The default condition (the case's `shell.edge`) applies to every boundary segment - an element
// side that belongs to one element only - that no named support covers; a segment is covered by
// a set when both its end nodes are in it. So naming `x-` free leaves the other sides with the
// default, and the corners they share with `x-` keep it too (a free side meeting a clamped one
// has a clamped corner). Symmetry planes of a quarter model count as named.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "model/mesh.hpp"
#include "model/supports.hpp"

namespace si {

enum class SupportType { kClamped, kHinged, kSimplySupported, kSymmetry, kDisplacement, kFree };

// The dofs a prescribed displacement can name: the global translations (mm) and the rotations
// about the node's reference axes v1, v2 (shell_element.hpp; zero only).
enum class SupportDof { kUx, kUy, kUz, kTheta1, kTheta2 };

struct NamedSupportSpec {
  std::string on;  // node set
  SupportType type = SupportType::kClamped;
  int symmetry_axis = -1;  // kSymmetry: plane normal e_x, e_y, e_z (0, 1, 2); -1: from the set
  std::vector<std::pair<SupportDof, double>> values;  // kDisplacement: mm, rotations 0
  Where where;                                        // the entry in the case file, for messages
};

struct SupportPlan {
  std::vector<Support> supports;
  std::vector<PrescribedDisplacement> displacements;  // the non-zero translations
};

// The supports of the named entries plus `default_type` on the uncovered boundary (stored as the
// node set "default_edge" when it is not empty and default_type is not kFree), with
// `covered_sets` (e.g. the symmetry planes a caller supports itself) counting as named.
// Errors carry the entry's `where`: an unknown set (listing the available ones), a symmetry
// entry whose plane cannot be inferred (its nodes do not share one coordinate), a non-zero
// rotation.
SupportPlan plan_supports(Mesh& mesh, const std::vector<NamedSupportSpec>& named,
                          SupportType default_type, const std::vector<std::string>& covered_sets);

// For a flat mesh in a plane z = const (all directors +-e_z): adds the fewest of u_x, u_y at
// `centre` and u_y at `far_node` that remove the in-plane rigid-body motions the plan leaves
// free (simply supported and free edges do not hold them). No-op for other meshes.
void hold_inplane_rigid_body(const Mesh& mesh, const std::string& centre,
                             const std::string& far_node, SupportPlan& plan);

}  // namespace si
