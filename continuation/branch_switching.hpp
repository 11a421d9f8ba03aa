// Branch switching at a located simple bifurcation point u* (Keller 1977, §5; Seydel 2010, §5.6;
// Allgower & Georg 2003, §8.2). The event (a stability_change classified as a bifurcation) carries
// the critical mode phi and the fundamental branch's unit tangent t at u*. The predictor direction
// is phi, orthogonalised against t in the arclength metric:
//     d = (phi - <phi, t> t) / ||phi - <phi, t> t||,     phi = (mode, 0)
// and the first point of the new branch solves F(u) = 0 with <d, u - u*> = ds (the hyperplane at
// distance ds along d: the new branch, tangent to a combination with a nonzero d component, crosses
// it near u* + ds d, while the fundamental branch, tangent to t, which is orthogonal to d, does
// not). Pseudo-arclength continuation then follows the new branch from that point, its first
// tangent oriented along d. direction = -1 takes -d: the other half of the new branch. Every point
// and event of the returned branch carries branch_id; the branch starts at its first point, ds
// from u* (J is singular at u* itself, where the branch's tangent is not unique).
#pragma once

#include "continuation/pseudo_arclength.hpp"

namespace si::cont {

struct BranchSwitch {
  int direction = 1;  // +1: along d, -1: along -d
  double step = 0.0;  // ds; 0 = Settings::step_initial. Halved on failure down to step_min.
  int branch_id = 1;  // the id of the new branch's points and events
};

// Throws std::invalid_argument when `bifurcation` is not a stability_change classified as a
// bifurcation with its mode and tangent (e.g. from a checkpoint written without x), or when the
// options are out of range. A first point that cannot be found gives Status::kStartFailed.
Branch switch_branch(Problem& problem, const Event& bifurcation, const Settings& settings,
                     const BranchSwitch& options = {}, const Callback& callback = {});

}  // namespace si::cont
