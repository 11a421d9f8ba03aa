// MacNeal & Harder (1985) twisted beam (linear.md): length 12 along x, width 1.1, pretwisted by
// 90 deg from root (x = 0, width along y) to tip (x = 12, width along z). The mid-surface is the
// helicoid p(x, w) = (x, w cos a(x), w sin a(x)), a(x) = (pi/2) x / 12, |w| <= 0.55: its
// straight generators across the width are exact, so all nodes lie on it. Directors are the
// exact helicoid normals (-w a', -sin a, cos a) / |.|, +z at the root centre.
//
// n_length x n_width elements (MacNeal-Harder use 12 x 2; Ko et al. 2017 refine further).
// Node sets: "root" (x = 0), "tip" (x = length).
#pragma once

#include "model/mesh.hpp"

namespace si {

struct TwistedBeamSpec {
  double length = 12;
  double width = 1.1;
  double twist_deg = 90;  // root to tip
  int n_length = 12;
  int n_width = 2;
};

Mesh twisted_beam_mesh(const TwistedBeamSpec& spec = {});

}  // namespace si
