// A test fixture the plate rests on (docs/case-file.md `fixture`): a rigid flat support frame
// under the plate's back face, which the plate may lift off (indentation/support_frame.hpp), and
// clamps at given points. The plate's centre, where the indenter presses, is the origin in plan.
//  * ASTM D7136/D7136M (drop-weight impact; its support fixture also serves quasi-static
//    indentation): a 150 x 100 mm specimen on a frame with a 125 x 75 mm rectangular cut-out,
//    held by four rubber-tipped clamps.
//  * ASTM D6264/D6264M (quasi-static indentation), edge-supported: the specimen on a frame with a
//    circular opening of given diameter; rigidly backed: the whole back face on a flat base.
#pragma once

#include <vector>

#include "core/linalg.hpp"

namespace si {

enum class FixtureType { kNone, kAstmD7136, kAstmD6264Opening, kAstmD6264Backed };

struct FixtureSpec {
  FixtureType type = FixtureType::kNone;
  double window_x = 125.0;        // mm, D7136 cut-out along x (the specimen's 150 mm side)
  double window_y = 75.0;         // mm, D7136 cut-out along y
  double opening_diameter = 0.0;  // mm, D6264 edge-supported: the frame's circular opening
  // Plan positions (x, y) of the clamp tips, mm. A clamp holds the node nearest its tip against
  // the frame (u_z = 0, rotations and in-plane motion free: a rubber tip's point support).
  std::vector<Vector2d> clamps;
};

// The presets' plate, mm: the D7136 (and D6264) specimen, 150 x 100 mm.
constexpr double kFixtureSpecimenX = 150.0;
constexpr double kFixtureSpecimenY = 100.0;

// The clamp tips of the D7136 preset: on the frame beside the cut-out's long edges, 12.5 mm in from
// its short edges, halfway between the cut-out and the specimen's edge: (+-50, +-43.75) mm. The
// standard's figure places four clamps around the cut-out; these positions are this program's
// reading of it, not numbers the standard states: give yours with `fixture.clamps`.
std::vector<Vector2d> astm_d7136_clamps();

}  // namespace si
