// The force a case predicts at given travels (io/force_travel.hpp): exact stops at the travels
// (the pseudo-arclength branch of the same case agrees at its end point, where it stops exactly
// too), and a warm start from another run's states giving the full run's forces with fewer
// Newton iterations.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "analysis/indentation_run.hpp"
#include "io/case_file.hpp"
#include "io/case_overrides.hpp"
#include "io/force_travel.hpp"

namespace si {
namespace {

const char* kCoarseCap =
    "material: paper-carbon-epoxy\n"
    "laminate: {layup: \"[0/0]2S\", ply_thickness: 0.475 mm}\n"
    "mesh: {size_apex: 1.5 mm, size_edge: 4 mm, refine_radius: 8 mm, symmetry: quarter}\n"
    "contact: {local: yang_sun}\n"
    "path: {depth_max: 2 mm, step: 0.1 mm}\n";

CaseFile with_e3(double e3) {
  YAML::Emitter e;
  e << with_numeric_values(YAML::Load(kCoarseCap), {{"material.E3", Dimension::kStress, e3}},
                           "cap");
  return parse_case_file(e.c_str(), "cap");
}

TEST(ForceTravel, StopsAtEveryTravelAndAgreesWithThePseudoArclengthEndPoint) {
  const std::vector<double> travels{0.0, 0.25, 0.7, 1.3, 2.0};
  const ForceTravel f = run_force_travel(with_e3(10000.0), travels, 1);
  ASSERT_TRUE(f.ok) << f.failure;
  EXPECT_FALSE(f.warm);
  ASSERT_EQ(f.force.size(), travels.size());
  EXPECT_EQ(f.force[0], 0.0);  // first touch
  for (std::size_t k = 1; k < travels.size(); ++k) EXPECT_GT(f.force[k], f.force[k - 1]);
  // The case's own pseudo-arclength path ends exactly on depth_max = 2 mm (continuation clips
  // the last step to the bound): the same equilibrium, to the Newton tolerance.
  IndentationSetup setup(with_e3(10000.0), 1);
  const PathResult r = run_indentation_path(setup);
  ASSERT_NEAR(r.points.back().state.depth, 2.0, 1e-12);
  EXPECT_NEAR(f.force.back(), r.points.back().state.force, 1e-7 * f.force.back());
}

TEST(ForceTravel, WarmStartGivesTheFullRunsForcesWithFewerIterations) {
  const std::vector<double> travels{0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0};
  const ForceTravel first = run_force_travel(with_e3(10000.0), travels, 1);
  ASSERT_TRUE(first.ok) << first.failure;
  for (const double e3 : {10100.0, 13000.0}) {
    const ForceTravel cold = run_force_travel(with_e3(e3), travels, 1);
    const ForceTravel warm = run_force_travel(with_e3(e3), travels, 1, {}, &first.states);
    ASSERT_TRUE(cold.ok && warm.ok) << cold.failure << warm.failure;
    EXPECT_TRUE(warm.warm);
    if (e3 < 10500.0) {  // 1 % away; from 30 % away the Newton iterations are about the same
      EXPECT_LT(warm.newton_iterations, cold.newton_iterations) << e3;
    }
    for (std::size_t k = 0; k < travels.size(); ++k)
      EXPECT_NEAR(warm.force[k], cold.force[k], 1e-7 * cold.force[k]) << e3 << " " << travels[k];
  }
  // States of other travels do not fit: the full path runs instead.
  const ForceTravel other = run_force_travel(with_e3(10000.0), {0.5, 1.0}, 1, {}, &first.states);
  ASSERT_TRUE(other.ok);
  EXPECT_FALSE(other.warm);
}

TEST(ForceTravel, NothingToRunToIsAFailure) {
  const ForceTravel f = run_force_travel(with_e3(10000.0), {0.0}, 1);
  EXPECT_FALSE(f.ok);
  EXPECT_FALSE(f.failure.empty());
}

}  // namespace
}  // namespace si
