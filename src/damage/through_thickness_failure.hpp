// Failure indices through the thickness at one in-plane point: the value-type step between the
// 3-D stress recovery (section/through_thickness_recovery.hpp) and whatever monitors them (a path's
// events, a VTU field, a CSV at chosen points). Recovered stresses in, indices out.
//
// Ply criteria (max stress, Tsai-Wu, Hashin) are evaluated at the bottom, middle and top of every
// ply; the interlaminar criterion at every interface between two plies, in the material axes of
// the ply below and of the ply above (sigma33, sigma13, sigma23 are continuous there), the larger
// index counting. The strengths are taken from each ply's material once, at construction, so a
// missing strength is refused before any stress is computed.
#pragma once

#include <vector>

#include "damage/criterion_strengths.hpp"
#include "damage/failure_index.hpp"
#include "section/laminate.hpp"
#include "section/through_thickness_recovery.hpp"

namespace si {

enum class PlyPosition { kBottom, kMiddle, kTop };

// One evaluation point: a ply point (ply criteria) or an interface (interlaminar criterion;
// `ply` is then the ply above the interface, 1 .. N-1, and position kBottom).
struct FailurePoint {
  int ply = 0;
  PlyPosition position = PlyPosition::kBottom;
  double x3 = 0;  // mm from the mid-surface
  FailureIndex index;
};

struct CriterionFailure {
  Criterion criterion;
  std::vector<FailurePoint> points;  // bottom ply first
  FailurePoint governing;            // the point of the largest index
};

class ThroughThicknessFailure {
 public:
  // Throws an input si::Error naming the material and key when a ply's material lacks a strength
  // that one of the criteria reads (criterion_strengths.hpp).
  ThroughThicknessFailure(const Laminate& laminate, std::vector<Criterion> criteria);

  // `recovered` must be recover_through_thickness(section, state, 3) of this laminate's section:
  // bottom, middle and top of every ply, bottom ply first. One result per criterion, in the order
  // given at construction.
  std::vector<CriterionFailure> evaluate(const std::vector<RecoveredPoint>& recovered) const;

 private:
  CriterionFailure evaluate_plies(Criterion c, const std::vector<Strengths>& strengths,
                                  const std::vector<RecoveredPoint>& recovered) const;
  CriterionFailure evaluate_interfaces(const std::vector<Strengths>& strengths,
                                       const std::vector<RecoveredPoint>& recovered) const;

  std::vector<double> angles_deg_;
  std::vector<Criterion> criteria_;
  std::vector<std::vector<Strengths>> strengths_;  // [criterion][ply]
};

}  // namespace si
