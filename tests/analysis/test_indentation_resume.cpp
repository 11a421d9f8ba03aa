// Issue 5: a killed run resumed from its checkpoint reproduces the uninterrupted run's path, for
// both continuation methods; bit for bit since issue 13.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "../indentation/indentation_test_support.hpp"
#include "analysis/indentation_run.hpp"
#include "analysis/path_columns.hpp"
#include "core/error.hpp"

namespace si {
namespace {

CaseFile resume_case(PathMethod method, LocalContactModel local, LocalSupport support) {
  CaseFile c = testing::coarse_cap_path_case("[0/0]2S", method, 1.0, 0.1, 0.15);
  c.contact.local = local;
  c.contact.local_support = support;
  return c;
}

struct Killed : std::runtime_error {
  Killed() : std::runtime_error("killed") {}
};

void expect_resume_reproduces(PathMethod method, const std::string& name,
                              LocalContactModel local = LocalContactModel::kNone,
                              LocalSupport support = LocalSupport::kHalfSpace, int kill_after = 5) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  PathControl control;
  control.checkpoint = (dir / "checkpoint.json").string();
  control.checkpoint_interval = 3;

  // The uninterrupted run checkpoints at the same interval: the solver caches are dropped at
  // each checkpoint, which changes the last bits of the path (not more than the Krylov
  // tolerance), so only runs with the same interval agree bit for bit.
  PathControl whole_control = control;
  whole_control.checkpoint = (dir / "whole.json").string();
  IndentationSetup whole(resume_case(method, local, support), 1);
  const PathResult a = run_indentation_path(whole, {}, whole_control);
  ASSERT_TRUE(a.completed) << a.reason;
  ASSERT_GT(a.points.size(), 7u);

  // Killed in the callback of the kill_after-th point (the start is the first; step k's
  // checkpoint is written after its callback): the last checkpoint is that of this step.
  const int checkpointed =
      (kill_after - 2) / control.checkpoint_interval * control.checkpoint_interval;
  {
    IndentationSetup first(resume_case(method, local, support), 1);
    int seen = 0;
    const auto kill_after_five = [&](const PathPoint&, const cont::Vector&) {
      if (++seen == kill_after) throw Killed();
      return true;
    };
    EXPECT_THROW(run_indentation_path(first, kill_after_five, control), Killed);
  }
  IndentationSetup second(resume_case(method, local, support), 1);
  control.resume = true;
  std::size_t computed = 0;  // points computed after the resume (the others come from disk)
  const auto count = [&](const PathPoint&, const cont::Vector&) { return ++computed > 0; };
  const PathResult b = run_indentation_path(second, count, control);
  ASSERT_TRUE(b.completed) << b.reason;
  EXPECT_LE(computed, a.points.size() - checkpointed);  // it did start from the checkpoint
  ASSERT_EQ(a.points.size(), b.points.size());
  // Bit for bit (issue 13 item 13): the solver caches are dropped at every checkpoint, so the
  // resumed run takes the uninterrupted run's steps exactly (it differed by up to 1.4e-10 in
  // force before). Every column of path.csv, and the slopes path_grid.csv interpolates with.
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(path_point_values(a.points[i]), path_point_values(b.points[i])) << "point " << i;
    const Eigen::VectorXd& sa = a.points[i].depth_slopes;
    const Eigen::VectorXd& sb = b.points[i].depth_slopes;
    ASSERT_EQ(sa.size(), sb.size()) << i;
    for (Eigen::Index k = 0; k < sa.size(); ++k)
      EXPECT_TRUE(sa[k] == sb[k] || (std::isnan(sa[k]) && std::isnan(sb[k]))) << i << " " << k;
  }
  ASSERT_EQ(a.final_unknowns.size(), b.final_unknowns.size());
  EXPECT_TRUE(a.final_unknowns == b.final_unknowns);
}

TEST(IndentationResume, PseudoArclengthResumedRunReproducesThePath) {
  expect_resume_reproduces(PathMethod::kPseudoArclength, "shellindent_resume_arclength");
}

TEST(IndentationResume, NaturalResumedRunReproducesThePath) {
  expect_resume_reproduces(PathMethod::kNatural, "shellindent_resume_natural");
}

// Issue 7: the local approach alpha is one more unknown of the checkpoint.
TEST(IndentationResume, PseudoArclengthWithYangSunLocalLawReproducesThePath) {
  expect_resume_reproduces(PathMethod::kPseudoArclength, "shellindent_resume_yang_sun",
                           LocalContactModel::kYangSun);
}

// The elastic face's zone, which widens with the contact (elastic_face.hpp), is part of the
// checkpoint: a resumed run couples the same nodes as the uninterrupted one. The zone widens at
// step 4 here; killed at step 7, the run resumes from step 6's checkpoint.
TEST(IndentationResume, PseudoArclengthWithTheElasticFaceReproducesThePath) {
  expect_resume_reproduces(PathMethod::kPseudoArclength, "shellindent_resume_elastic_face",
                           LocalContactModel::kAnisotropic, LocalSupport::kShell, 8);
}

// A checkpoint whose zone is not one the run can have reached (below a quarter of its bound,
// beyond the bound, not one number) is refused as an input error naming the checkpoint, rather
// than resumed with other couplings than the run that wrote it.
TEST(IndentationResume, AnEditedZoneIsRefused) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "shellindent_resume_edited_zone";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const CaseFile c = resume_case(PathMethod::kPseudoArclength, LocalContactModel::kAnisotropic,
                                 LocalSupport::kShell);
  PathControl control;
  control.checkpoint = (dir / "checkpoint.json").string();
  control.checkpoint_interval = 3;
  {
    IndentationSetup first(c, 1);
    int seen = 0;
    const auto kill = [&](const PathPoint&, const cont::Vector&) {
      if (++seen == 8) throw Killed();
      return true;
    };
    EXPECT_THROW(run_indentation_path(first, kill, control), Killed);
  }
  nlohmann::json written;
  std::ifstream(control.checkpoint) >> written;
  const nlohmann::json zone = written["attachment"]["local_state"];
  ASSERT_TRUE(zone.is_array() && zone.size() == 1 && zone[0].is_number()) << zone.dump();
  const double radius = zone[0].get<double>();
  control.resume = true;
  for (const nlohmann::json& edited :
       {nlohmann::json::array({-radius}), nlohmann::json::array({1e3 * radius}),
        nlohmann::json::array({0.01 * radius}), nlohmann::json::array({"x"}),
        nlohmann::json::array(), nlohmann::json::array({radius, radius})}) {
    nlohmann::json cp = written;
    cp["attachment"]["local_state"] = edited;
    std::ofstream(control.checkpoint) << cp.dump();
    IndentationSetup second(c, 1);
    try {
      run_indentation_path(second, {}, control);
      ADD_FAILURE() << "resumed with the zone " << edited.dump();
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::kInput) << edited.dump();
      EXPECT_NE(std::string(e.what()).find("checkpoint"), std::string::npos) << e.what();
    }
  }
  // The checkpoint as written resumes (the refusals above are the edits').
  std::ofstream(control.checkpoint) << written.dump();
  IndentationSetup third(c, 1);
  EXPECT_TRUE(run_indentation_path(third, {}, control).completed);
}

}  // namespace
}  // namespace si
