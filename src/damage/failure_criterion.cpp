#include "damage/failure_criterion.hpp"

#include "damage/hashin.hpp"
#include "damage/max_stress.hpp"
#include "damage/quadratic_delamination.hpp"
#include "damage/tsai_wu.hpp"

namespace si {

FailureIndex evaluate_criterion(Criterion criterion, const MaterialStress& stress,
                                const Strengths& strengths) {
  switch (criterion) {
    case Criterion::kMaxStress:
      return max_stress(stress, strengths);
    case Criterion::kTsaiWu:
      return tsai_wu(stress, strengths);
    case Criterion::kHashin:
      return hashin(stress, strengths);
    case Criterion::kQuadraticDelamination:
      return quadratic_delamination(stress, strengths);
  }
  return {};
}

}  // namespace si
