// A fixture (fixture_spec.hpp) put on a flat plate's mesh: which nodes rest on the frame, which
// the clamps hold, and the mesh lines on the cut-out's edges.
#pragma once

#include <string>
#include <vector>

#include "model/fixture_spec.hpp"
#include "model/mesh.hpp"
#include "model/supports.hpp"

namespace si {

// Node sets of the fixture on `mesh` (a flat plate in z = const centred on the origin in plan; a
// quarter model x >= 0, y >= 0 keeps the clamps in its quarter):
//   "frame"       the nodes over the frame (outside the cut-out or opening, or every node when
//                 fully backed; the cut-out's edges belong to the frame),
//   "window_edge" the nodes on the edge of the cut-out or opening (within 1e-6 of its size),
//   "clamps"      the node nearest each clamp tip (none without clamps),
// and the clamps' supports (u_z = 0) appended to `supports`. Returns the frame's nodes. Throws an
// input error naming `fixture.window`, `fixture.opening_diameter` or `fixture.clamps` (with
// `file`) for a cut-out or opening not inside the plate, or a clamp tip off the frame.
std::vector<int> apply_fixture(const FixtureSpec& fixture, const std::string& file, Mesh& mesh,
                               std::vector<Support>& supports);

// `half` (stations from the centre outwards) with a station at `at`: the nearest station moved
// there if it is within a third of its element, else one inserted. No-op unless 0 < at < end.
std::vector<double> with_station(std::vector<double> half, double at);

}  // namespace si
