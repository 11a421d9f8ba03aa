// Checkpoints: exact JSON round trip, and a killed run resumed from its last checkpoint
// reproduces the uninterrupted run (acceptance: to 1e-10).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "branch_test_support.hpp"
#include "bratu_problem.hpp"
#include "continuation/checkpoint.hpp"
#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"

namespace si::cont {
namespace {

namespace fs = std::filesystem;

// A per-test file in gtest's temporary directory (tests may run in parallel under ctest).
std::string temp_path(const std::string& name) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  return testing::TempDir() + "cont_" + info->name() + "_" + name;
}

// A plain writer (branch_test_support.hpp) that records the paths it was given.
struct RecordingWriter {
  std::vector<std::string> paths;
  FileWriter writer() {
    return [this](const std::string& path, const std::string& content) {
      paths.push_back(path);
      test::plain_file_writer()(path, content);
    };
  }
};

Settings bratu_settings(Method method) {
  Settings s;
  s.method = method;
  s.step_initial = 0.1;
  s.step_max = 0.15;
  s.p_min = 0.5;
  s.p_max = method == Method::kNatural ? 3.45 : 5.0;  // natural stops below the fold
  s.max_steps = 40;
  s.newton.residual_scale = 10.0;
  s.extremum_monitors = {"u_max"};
  s.predictor = Predictor::kSecant;  // the resumed run needs the previous point too
  return s;
}

Branch run_fresh(Method method, test::BratuProblem& bratu, const Settings& s,
                 const Callback& callback = {}) {
  const Vector x0 = Vector::Zero(bratu.size());
  return method == Method::kNatural ? natural(bratu, x0, 1.0, s, callback)
                                    : pseudo_arclength(bratu, x0, 1.0, s, callback);
}

// b's points before index `without_x` come from a checkpoint written without x.
void expect_same_branch(const Branch& a, const Branch& b, double tol, std::size_t without_x) {
  EXPECT_EQ(a.status, b.status);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_NEAR(a.points[i].p, b.points[i].p, tol) << "point " << i;
    EXPECT_LE((a.points[i].monitors - b.points[i].monitors).lpNorm<Eigen::Infinity>(), tol);
    if (i < without_x) {
      EXPECT_EQ(b.points[i].x.size(), 0);
      continue;
    }
    EXPECT_LE((a.points[i].x - b.points[i].x).lpNorm<Eigen::Infinity>(), tol) << "point " << i;
    EXPECT_EQ(a.points[i].newton_iterations, b.points[i].newton_iterations);
  }
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].name, b.events[i].name);
    EXPECT_NEAR(a.events[i].p, b.events[i].p, tol);
    if (b.events[i].step < static_cast<int>(without_x)) {
      EXPECT_EQ(b.events[i].x.size(), 0);  // found before the checkpoint, written without x
      continue;
    }
    EXPECT_LE((a.events[i].x - b.events[i].x).lpNorm<Eigen::Infinity>(), tol) << "event " << i;
  }
}

// The run is "killed" after step 13: the callback copies the checkpoint on disk at that moment
// (written at step 10) and stops. Resuming from the copy must give the uninterrupted branch.
void expect_resume_reproduces(Method method, bool keeps_x, double natural_corrector_slope = 0.0) {
  const int n = 100;
  test::BratuProblem bratu(n);
  Settings plain = bratu_settings(method);
  plain.natural_corrector_slope = natural_corrector_slope;
  const Branch reference = run_fresh(method, bratu, plain);
  ASSERT_GT(reference.points.size(), 15u);  // so that the kill at step 13 interrupts it

  Settings s = plain;
  RecordingWriter files;
  s.checkpoint_writer = files.writer();
  s.checkpoint_path = temp_path("run.json");
  s.checkpoint_interval = 5;
  s.checkpoint_keeps_x = keeps_x;
  const std::string killed = temp_path("killed.json");
  run_fresh(method, bratu, s, [&](const Point&, const Branch& branch) {
    if (branch.points.size() < 14) return true;
    fs::copy_file(s.checkpoint_path, killed, fs::copy_options::overwrite_existing);
    return false;
  });
  ASSERT_TRUE(fs::exists(killed)) << "the run ended before step 13";
  // The start and steps 5 and 10, all through the caller's writer; none at the stop (a run
  // stopped by its callback keeps its last periodic checkpoint, tracer.cpp finish()).
  EXPECT_EQ(files.paths, std::vector<std::string>(3, s.checkpoint_path));
  const Checkpoint checkpoint = load_checkpoint(killed);
  EXPECT_EQ(checkpoint.branch.points.size(), 11u);  // start + 10 steps
  EXPECT_EQ(checkpoint.branch.status, Status::kRunning);

  const Branch resumed = method == Method::kNatural ? natural(bratu, checkpoint, plain)
                                                    : pseudo_arclength(bratu, checkpoint, plain);
  expect_same_branch(reference, resumed, 1e-10, keeps_x ? 0 : checkpoint.branch.points.size());
  fs::remove(s.checkpoint_path);
  fs::remove(killed);
}

TEST(ContCheckpoint, ResumePseudoArclengthReproducesUninterruptedRun) {
  expect_resume_reproduces(Method::kPseudoArclength, true);
}

// With steep steps corrected at fixed p the step after the resume reads the previous point's
// dp/ds (State::previous_tangent_p), which the checkpoint keeps.
TEST(ContCheckpoint, ResumeWithNaturalCorrectorOnSteepStepsReproducesUninterruptedRun) {
  expect_resume_reproduces(Method::kPseudoArclength, true, 0.5);
}

TEST(ContCheckpoint, ResumeNaturalReproducesUninterruptedRun) {
  expect_resume_reproduces(Method::kNatural, true);
}

// Without every point's x the checkpoint still resumes exactly (the state keeps its x).
TEST(ContCheckpoint, ResumeFromCheckpointWithoutPointStates) {
  expect_resume_reproduces(Method::kPseudoArclength, false);
}

// x - p = 0, counting Problem::reset_solver_caches() calls.
class CountingLine final : public Problem {
 public:
  int size() const override { return 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F = Vector::Constant(1, x[0] - p);
    return true;
  }
  bool factorize(const Vector&, double) override { return true; }
  bool solve(Vector&) override { return true; }  // dF/dx = 1
  void reset_solver_caches() override { ++resets; }
  int resets = 0;
};

Settings line_settings(const std::string& path) {
  Settings s;
  s.method = Method::kNatural;
  s.step_initial = s.step_max = 0.1;
  s.p_min = 0.0;
  s.p_max = 1.0;
  s.checkpoint_path = path;
  s.checkpoint_writer = test::plain_file_writer();
  s.checkpoint_interval = 3;
  return s;
}

// Issue 13 items 12-13: the caller's record goes into the same file as the branch, written after
// the callback saw the point (so it always holds the checkpoint's points); the solver caches are
// dropped after every periodic checkpoint and before a resume; a run stopped by its callback
// keeps its last periodic checkpoint.
TEST(ContCheckpoint, AttachmentIsInStepWithTheBranchAndCachesAreDroppedAtCheckpoints) {
  CountingLine line;
  Settings s = line_settings(temp_path("line.json"));
  int seen = 0;
  s.checkpoint_attachment = [&] { return nlohmann::json{{"seen", seen}}; };
  const Callback count = [&](const Point&, const Branch&) { return ++seen > 0; };
  const Branch whole = natural(line, Vector::Zero(1), 0.0, s, count);
  ASSERT_EQ(whole.status, Status::kReachedBound);
  const int steps = static_cast<int>(whole.points.size()) - 1;
  EXPECT_EQ(line.resets, steps / 3 + 1);  // steps 0, 3, 6, 9
  const Checkpoint end = load_checkpoint(s.checkpoint_path);
  EXPECT_EQ(end.attachment.at("seen").get<std::size_t>(), end.branch.points.size());

  CountingLine stopped;
  seen = 0;
  const Callback stop_at_five = [&](const Point&, const Branch&) { return ++seen < 5; };
  natural(stopped, Vector::Zero(1), 0.0, s, stop_at_five);
  const Checkpoint kept = load_checkpoint(s.checkpoint_path);
  EXPECT_EQ(kept.branch.points.size(), 4u);  // the step-3 checkpoint, not the stop at step 4
  EXPECT_EQ(kept.branch.status, Status::kRunning);
  EXPECT_EQ(kept.attachment.at("seen").get<int>(), 4);

  CountingLine resumed;
  const Branch rest = natural(resumed, kept, line_settings(temp_path("rest.json")));
  EXPECT_EQ(rest.points.size(), whole.points.size());
  EXPECT_GE(resumed.resets, 1);
  fs::remove(s.checkpoint_path);
  fs::remove(temp_path("rest.json"));
}

// What a resume would continue from, as the run reports it (Branch::checkpointed): the CLI's
// stop message tells the user the depth from it.
TEST(ContCheckpoint, TheBranchSaysHowManyPointsItsCheckpointHolds) {
  Settings s = line_settings(temp_path("held.json"));
  CountingLine line;
  int seen = 0;
  const Callback stop_at_five = [&](const Point&, const Branch&) { return ++seen < 5; };
  const Branch stopped = natural(line, Vector::Zero(1), 0.0, s, stop_at_five);
  ASSERT_EQ(stopped.status, Status::kStoppedByCallback);
  EXPECT_EQ(stopped.points.size(), 5u);
  EXPECT_EQ(stopped.checkpointed, 4u);  // the step-3 checkpoint

  const Checkpoint kept = load_checkpoint(s.checkpoint_path);
  const Callback stop_at_once = [](const Point&, const Branch&) { return false; };
  const Branch resumed_and_stopped = natural(line, kept, s, stop_at_once);
  EXPECT_EQ(resumed_and_stopped.checkpointed, 4u);  // the one it resumed from

  const Branch whole = natural(line, Vector::Zero(1), 0.0, s);
  ASSERT_EQ(whole.status, Status::kReachedBound);
  EXPECT_EQ(whole.checkpointed, whole.points.size());  // written at the end

  s.checkpoint_path.clear();
  s.checkpoint_interval = 0;
  EXPECT_EQ(natural(line, Vector::Zero(1), 0.0, s).checkpointed, 0u);
  fs::remove(temp_path("held.json"));
}

TEST(ContCheckpoint, JsonRoundTripIsExact) {
  Checkpoint c;
  c.method = Method::kNatural;
  Point pt;
  pt.x = Vector{{0.1, 1.0 / 3.0, -2.5e-300, std::nextafter(1.0, 2.0)}};
  pt.p = M_PI;
  pt.tangent_p = -std::sqrt(0.5);
  pt.monitors = Vector{{std::numeric_limits<double>::quiet_NaN(), 1e300}};
  pt.signature = {1, 0, 1};
  pt.jacobian_sign = -1;
  pt.newton_iterations = 3;
  pt.step = 0.123456789012345678;
  c.branch.monitor_names = {"a", "b"};
  c.branch.points = {pt, pt};
  Event e;
  e.type = EventType::kInflection;
  e.name = event_type_name(e.type);
  e.monitor = "a";
  e.against = "b";
  e.p = 1.0 / 7.0;
  e.x = pt.x;
  e.located = true;
  c.branch.events = {e};
  c.state.current.point = pt;
  c.state.current.tangent_x = Vector{{std::exp(1.0), -std::numeric_limits<double>::infinity()}};
  c.state.step = 1e-7 / 3.0;
  c.state.has_previous = true;
  c.state.previous_x = pt.x * 0.7;
  c.state.previous_p = 2.0 / 3.0;
  c.state.previous_tangent_p = -1.0 / 3.0;

  const std::string path = temp_path("roundtrip.json");
  RecordingWriter files;
  save_checkpoint(path, c, true, files.writer());
  EXPECT_EQ(files.paths, std::vector<std::string>{path});  // through the caller's writer only
  EXPECT_EQ(checkpoint_text(c, true).back(), '\n');
  const Checkpoint r = load_checkpoint(path);
  fs::remove(path);

  EXPECT_EQ(r.method, Method::kNatural);
  const Point& q = r.state.current.point;
  EXPECT_TRUE((q.x.array() == pt.x.array()).all());  // bit for bit
  EXPECT_EQ(q.p, pt.p);
  EXPECT_EQ(q.tangent_p, pt.tangent_p);
  EXPECT_TRUE(std::isnan(q.monitors(0)));
  EXPECT_EQ(q.monitors(1), 1e300);
  EXPECT_EQ(q.signature, pt.signature);
  EXPECT_EQ(q.step, pt.step);
  EXPECT_EQ(r.state.current.tangent_x(0), std::exp(1.0));
  EXPECT_EQ(r.state.current.tangent_x(1), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(r.state.step, c.state.step);
  EXPECT_TRUE((r.state.previous_x.array() == c.state.previous_x.array()).all());
  EXPECT_EQ(r.state.previous_tangent_p, c.state.previous_tangent_p);
  ASSERT_EQ(r.branch.events.size(), 1u);
  EXPECT_EQ(r.branch.events[0].type, EventType::kInflection);
  EXPECT_EQ(r.branch.events[0].against, "b");
  EXPECT_EQ(r.branch.events[0].p, 1.0 / 7.0);
  EXPECT_TRUE((r.branch.events[0].x.array() == pt.x.array()).all());

  // Without the points' x (Settings::checkpoint_keeps_x = false) the events lose theirs too;
  // the state keeps its own.
  save_checkpoint(path, c, false, files.writer());
  const Checkpoint lean = load_checkpoint(path);
  fs::remove(path);
  EXPECT_EQ(lean.branch.points[0].x.size(), 0);
  EXPECT_EQ(lean.branch.events[0].x.size(), 0);
  EXPECT_EQ(lean.branch.events[0].p, 1.0 / 7.0);
  EXPECT_TRUE((lean.state.current.point.x.array() == pt.x.array()).all());
}

TEST(ContCheckpoint, PathWithoutWriterRejected) {
  Settings s = bratu_settings(Method::kPseudoArclength);
  s.checkpoint_path = temp_path("nowhere.json");
  EXPECT_THROW(s.validate(), std::invalid_argument);
  RecordingWriter files;
  s.checkpoint_writer = files.writer();
  EXPECT_NO_THROW(s.validate());
}

TEST(ContCheckpoint, MissingOrForeignFileRejectedWithItsName) {
  const std::string path = temp_path("foreign.json");
  EXPECT_THROW(load_checkpoint(path), std::runtime_error);
  {
    std::ofstream out(path);
    out << R"({"format": "something else", "version": 1})";
  }
  try {
    load_checkpoint(path);
    ADD_FAILURE() << "foreign file accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  fs::remove(path);
}

}  // namespace
}  // namespace si::cont
