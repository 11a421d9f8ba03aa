#include "damage/through_thickness_failure.hpp"

#include <string>
#include <utility>

#include "core/error.hpp"
#include "damage/failure_criterion.hpp"
#include "damage/quadratic_delamination.hpp"

namespace si {
namespace {

constexpr int kPointsPerPly = 3;  // bottom, middle, top

void require_layout(const std::vector<RecoveredPoint>& recovered, size_t plies) {
  if (recovered.size() != kPointsPerPly * plies)
    throw_input(
        "through-thickness failure needs the recovered bottom, middle and top of each of "
        "the " +
        std::to_string(plies) + " plies (got " + std::to_string(recovered.size()) + " points)");
}

FailurePoint larger(const FailurePoint& a, const FailurePoint& b) {
  return b.index.index > a.index.index ? b : a;
}

}  // namespace

ThroughThicknessFailure::ThroughThicknessFailure(const Laminate& laminate,
                                                 std::vector<Criterion> criteria)
    : criteria_(std::move(criteria)) {
  for (const Ply& ply : laminate.plies) angles_deg_.push_back(ply.angle_deg);
  for (Criterion c : criteria_) {
    std::vector<Strengths> per_ply;
    for (const Ply& ply : laminate.plies) per_ply.push_back(strengths_for(c, ply.material));
    strengths_.push_back(std::move(per_ply));
  }
}

std::vector<CriterionFailure> ThroughThicknessFailure::evaluate(
    const std::vector<RecoveredPoint>& recovered) const {
  require_layout(recovered, angles_deg_.size());
  std::vector<CriterionFailure> out;
  for (size_t i = 0; i < criteria_.size(); ++i)
    out.push_back(criteria_[i] == Criterion::kQuadraticDelamination
                      ? evaluate_interfaces(strengths_[i], recovered)
                      : evaluate_plies(criteria_[i], strengths_[i], recovered));
  return out;
}

CriterionFailure ThroughThicknessFailure::evaluate_plies(
    Criterion c, const std::vector<Strengths>& strengths,
    const std::vector<RecoveredPoint>& recovered) const {
  CriterionFailure out{c, {}, {}};
  for (size_t i = 0; i < recovered.size(); ++i) {
    const RecoveredPoint& r = recovered[i];
    FailurePoint p;
    p.ply = r.ply;
    p.position = static_cast<PlyPosition>(i % kPointsPerPly);
    p.x3 = r.x3;
    p.index =
        evaluate_criterion(c, to_material_axes(r.stress, angles_deg_[r.ply]), strengths[r.ply]);
    out.governing = i == 0 ? p : larger(out.governing, p);
    out.points.push_back(p);
  }
  return out;
}

CriterionFailure ThroughThicknessFailure::evaluate_interfaces(
    const std::vector<Strengths>& strengths, const std::vector<RecoveredPoint>& recovered) const {
  CriterionFailure out{Criterion::kQuadraticDelamination, {}, {}};
  const int plies = static_cast<int>(angles_deg_.size());
  for (int k = 1; k < plies; ++k) {
    // The top of ply k-1 and the bottom of ply k: the same interface seen from both sides.
    const RecoveredPoint& below = recovered[kPointsPerPly * (k - 1) + 2];
    const RecoveredPoint& above = recovered[kPointsPerPly * k];
    FailurePoint p;
    p.ply = k;
    p.position = PlyPosition::kBottom;
    p.x3 = above.x3;
    p.index = governing(
        quadratic_delamination(to_material_axes(below.stress, angles_deg_[k - 1]),
                               strengths[k - 1]),
        quadratic_delamination(to_material_axes(above.stress, angles_deg_[k]), strengths[k]));
    out.governing = k == 1 ? p : larger(out.governing, p);
    out.points.push_back(p);
  }
  return out;
}

}  // namespace si
