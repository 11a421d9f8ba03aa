// The named critical points (analysis/critical_points.hpp), each definition against a closed
// form or a different method, and what the detectors must not report:
//  * the onset of nonlinearity on T = k h + c h^3 against T_lin = k h: |c| h^2 = f k, so
//    h* = sqrt(f k / |c|) (stiffening and softening), and on a linear response piecewise in h
//    (nodes entering contact) times (1 + a h^2): h* = sqrt(f / a) whatever the kinks;
//  * none on an exactly linear path (the deviation is roundoff);
//  * the inflection of T(h): T = (h - 3)^3 + 2 h has its stiffness minimum at h = 3, T = h +
//    tanh(h - 2) its maximum at 2 (with exact slopes and from the values alone); none on an
//    exactly linear segment with roundoff, none at kinks where nodes enter contact;
//  * the limit points and bifurcations are the continuation's events, sorted by kind;
//  * on the paper's cap (coarse quarter mesh, [0/90]2S): the onset by bisection of natural
//    solves of the nonlinear and the linear cases agrees with the reported one within its
//    stated accuracy; the watch's trial solves (each from the solved states around it) give the
//    natural solve's force, solve a depth once, and near a solved depth take few iterations.
#include "analysis/critical_points.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../indentation/indentation_test_support.hpp"
#include "analysis/onset_watch.hpp"

namespace si {
namespace {

// A point at `depth` with force T, exact slope dT/dh (NaN: none) and the nodes `set` pressing.
PathPoint point(double depth, double T, double slope, const std::vector<int>& set = {1}) {
  PathPoint p;
  p.state.depth = depth;
  p.state.force = T;
  if (std::isfinite(slope)) p.depth_slopes = Eigen::VectorXd::Constant(1, slope);
  for (int n : set) {
    p.state.nodes.push_back(n);
    p.state.multipliers.push_back(1.0);
  }
  return p;
}

// T(h) with slope dT on depths 0, step, 2 step, ... <= end.
std::vector<PathPoint> sampled(const std::function<double(double)>& T,
                               const std::function<double(double)>& dT, double step, double end,
                               bool with_slopes = true) {
  std::vector<PathPoint> pts;
  for (int i = 0; i * step <= end + 1e-12; ++i) {
    const double h = i * step;
    pts.push_back(point(h, T(h), with_slopes ? dT(h) : std::nan("")));
  }
  return pts;
}

TEST(CriticalPoints, OnsetOfACubicResponseMatchesTheClosedForm) {
  const double k = 2000, f = 0.05;
  for (double c : {40.0, -40.0}) {  // stiffening (a plate's membrane) and softening (a cap)
    const auto pts = sampled([&](double h) { return k * h + c * h * h * h; },
                             [&](double h) { return k + 3 * c * h * h; }, 0.13, 3.0);
    CriticalPoints out;
    find_nonlinearity_onset(
        pts, 0, [&](double h) { return k * h; }, f, out);
    ASSERT_EQ(out.onset_status, OnsetStatus::kFound);
    const double exact = std::sqrt(f * k / std::abs(c));  // 1.5811 mm
    EXPECT_TRUE(out.onset->located);
    EXPECT_LE(std::abs(out.onset->depth - exact), out.onset->accuracy);
    EXPECT_LT(out.onset->accuracy, 0.01);  // Hermite against the secant: a real bound
    EXPECT_NEAR(out.onset->depth, exact, 1e-4);
    EXPECT_NEAR(out.onset->linear_force, k * out.onset->depth, 1e-9);
    // Without the exact slopes: the secant root and its bracket.
    const auto bare = sampled([&](double h) { return k * h + c * h * h * h; },
                              [&](double) { return 0.0; }, 0.13, 3.0, false);
    CriticalPoints out2;
    find_nonlinearity_onset(
        bare, 0, [&](double h) { return k * h; }, f, out2);
    ASSERT_EQ(out2.onset_status, OnsetStatus::kFound);
    EXPECT_FALSE(out2.onset->located);
    EXPECT_NEAR(out2.onset->accuracy, 0.13, 1e-12);
    EXPECT_LE(std::abs(out2.onset->depth - exact), out2.onset->accuracy);
  }
}

// T_lin piecewise linear with its slope rising at nodes entering contact (0.45, 0.9, 1.35 mm),
// T = T_lin (1 + a h^2): the onset h* = sqrt(f / a) = 1 mm lies next to a kink.
TEST(CriticalPoints, OnsetNextToContactKinksWithinItsStatedAccuracy) {
  const double a = 0.05, f = 0.05;
  const auto linear = [](double h) {
    double t = 0, slope = 1000, at = 0;
    for (double kink : {0.45, 0.9, 1.35, 1e9}) {
      const double end = std::min(h, kink);
      t += slope * (end - at);
      at = end;
      if (h <= kink) break;
      slope += 300;
    }
    return t;
  };
  const auto linear_slope = [](double h) {
    return 1000 + 300 * ((h > 0.45) + (h > 0.9) + (h > 1.35));
  };
  std::vector<PathPoint> pts;
  for (int i = 0; i <= 20; ++i) {
    const double h = 0.11 * i;
    const std::vector<int> set(1 + (h > 0.45) + (h > 0.9) + (h > 1.35), 7);
    pts.push_back(point(h, linear(h) * (1 + a * h * h),
                        linear_slope(h) * (1 + a * h * h) + linear(h) * 2 * a * h, set));
  }
  CriticalPoints out;
  find_nonlinearity_onset(pts, 0, linear, f, out);
  ASSERT_EQ(out.onset_status, OnsetStatus::kFound);
  EXPECT_LE(std::abs(out.onset->depth - 1.0), out.onset->accuracy);
  EXPECT_LT(out.onset->accuracy, 0.11 + 1e-12);
}

TEST(CriticalPoints, NoOnsetOnAnExactlyLinearPath) {
  const auto pts = sampled([](double h) { return 9e3 * h * (1 + 1e-13 * std::sin(7 * h)); },
                           [](double) { return 9e3; }, 0.1, 10.0);
  CriticalPoints out;
  find_nonlinearity_onset(
      pts, 0, [](double h) { return 9e3 * h; }, 0.05, out);
  EXPECT_EQ(out.onset_status, OnsetStatus::kNone);
  EXPECT_FALSE(out.onset.has_value());
  EXPECT_LT(out.max_deviation, 1e-12);
}

TEST(CriticalPoints, StiffnessMinimumOfACubicAtItsInflection) {
  for (bool slopes : {true, false}) {
    const auto pts = sampled([](double h) { return std::pow(h - 3, 3) + 2 * h; },
                             [](double h) { return 3 * (h - 3) * (h - 3) + 2; }, 0.1, 6.0, slopes);
    const auto found = force_inflections(pts, 0);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].kind, CriticalKind::kStiffnessMin);
    EXPECT_NEAR(found[0].depth, 3.0, 1e-6);  // T'' linear in h: interpolated exactly
    EXPECT_LE(std::abs(found[0].depth - 3.0), found[0].accuracy);
    EXPECT_NEAR(found[0].stiffness, 2.0, slopes ? 0.01 : 0.02);
    EXPECT_NEAR(found[0].force, 6.0, 1e-3);
  }
}

TEST(CriticalPoints, StiffnessMaximumOfATanhStep) {
  const auto pts = sampled([](double h) { return h + std::tanh(h - 2); },
                           [](double h) { return 2 - std::pow(std::tanh(h - 2), 2); }, 0.07, 4.0);
  const auto found = force_inflections(pts, 0);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, CriticalKind::kStiffnessMax);
  EXPECT_LE(std::abs(found[0].depth - 2.0), found[0].accuracy);
  EXPECT_NEAR(found[0].depth, 2.0, 1e-3);
}

// Roundoff shaped so that the second difference is + for 4 points then - for 4 on T = 9e3 h
// (the critical force's test, CriticalForce.NoInflectionInsideAnExactlyLinearSegment), with the
// slopes carrying roundoff of the same shape.
TEST(CriticalPoints, NoInflectionInsideAnExactlyLinearSegment) {
  const int d2[] = {1, 1, 1, 1, -1, -1, -1, -1};
  std::vector<double> noise = {0.0, 0.0};
  for (int s : d2) noise.push_back(2 * noise.back() - noise[noise.size() - 2] + s);
  for (bool slopes : {true, false}) {
    std::vector<PathPoint> pts;
    for (std::size_t i = 0; i < noise.size(); ++i) {
      const double h = 0.1 * static_cast<double>(i + 1);
      pts.push_back(point(h, 9e3 * h + 2.7e-8 * noise[i],
                          slopes ? 9e3 + 2.7e-7 * noise[i] : std::nan(""), {4, 5, 6}));
    }
    EXPECT_TRUE(force_inflections(pts, 0).empty());
  }
}

// A polyline whose slope rises at three kinks and falls at three, a node entering contact at
// each: the slope's extremum lies at a kink, and a kink is a contact event, not an inflection.
TEST(CriticalPoints, KinksWhereNodesEnterContactAreNotInflections) {
  const double slopes[] = {1, 2, 3, 4, 3.5, 3, 2.5};
  std::vector<PathPoint> pts = {point(0, 0, 1, {0})};
  std::vector<int> set = {0};
  double T = 0;
  for (int piece = 0; piece < 7; ++piece) {
    for (int j = 0; j < 4; ++j) {
      T += slopes[piece] * 0.5;
      pts.push_back(point(static_cast<double>(pts.size()) * 0.5, T, slopes[piece], set));
    }
    set.push_back(piece + 1);
  }
  EXPECT_TRUE(force_inflections(pts, 0).empty());
}

// The stiffness 10 + 2 (h - 3)^2 with a node entering contact every 0.13 mm (the stiffness
// falls by 2 % of its minimum within each contact set and jumps up where a node enters): no sign
// change of d2T/dh2 between two points of one contact set holds the minimum, as on the cap's
// fine meshes, but the well does: its fitted vertex at 3 mm within 0.05 mm and its accuracy.
// T is integrated exactly on each contact set; the same curve without kinks gives the exact
// sign change (one contact set: the curve-feature rules' root, linear in T'').
TEST(CriticalPoints, StiffnessMinimumAcrossContactKinksFromItsWell) {
  for (bool kinks : {true, false}) {
    const double period = 0.13, jump = kinks ? 0.2 : 0.0, step = 0.02;
    // s = 10 + 2 (h - 3)^2 + jump (0.5 - phase), phase = (h mod period) / period.
    const auto T = [&](double h) {
      const double pieces = std::floor(h / period), phase = h - pieces * period;
      // A whole period of the sawtooth integrates to zero.
      const double saw = jump * (0.5 * phase - 0.5 * phase * phase / period);
      return 10 * h + 2.0 / 3.0 * (std::pow(h - 3, 3) + 27) + saw;
    };
    std::vector<PathPoint> pts;
    for (int i = 0; i * step <= 6.0 + 1e-12; ++i) {
      const double h = i * step;
      const int set = kinks ? static_cast<int>(std::floor(h / period)) : 0;
      const double slope =
          10 + 2 * (h - 3) * (h - 3) + jump * (0.5 - std::fmod(h, period) / period);
      std::vector<int> nodes(static_cast<std::size_t>(set + 1));
      for (int n = 0; n <= set; ++n) nodes[static_cast<std::size_t>(n)] = n;
      pts.push_back(point(h, T(h), slope, nodes));
    }
    const auto found = force_inflections(pts, 0);
    ASSERT_EQ(found.size(), 1u) << kinks;
    EXPECT_EQ(found[0].kind, CriticalKind::kStiffnessMin);
    EXPECT_NEAR(found[0].depth, 3.0, kinks ? 0.05 : 1e-6);
    EXPECT_LE(std::abs(found[0].depth - 3.0), found[0].accuracy);
    EXPECT_NEAR(found[0].stiffness, 10.0, 0.1);
    EXPECT_NEAR(found[0].force, T(found[0].depth), 0.02);
  }
}

TEST(CriticalPoints, EventsSortedIntoLimitPointsAndBifurcations) {
  const auto event = [](cont::EventType type, const std::string& monitor, double depth,
                        cont::Criticality criticality = cont::Criticality::kNone) {
    cont::Event e;
    e.type = type;
    e.monitor = monitor;
    e.p = depth;
    e.monitors = Eigen::Vector2d(10 * depth, 0);
    e.accuracy = 1e-9;
    e.located = true;
    e.criticality = criticality;
    return e;
  };
  using T = cont::EventType;
  const std::vector<cont::Event> events = {
      event(T::kSignatureChange, "", 0.5),
      event(T::kMonitorMax, "force_N", 1.0),
      event(T::kMonitorMax, "k11_per_mm", 1.5),  // not a force
      event(T::kLimitPoint, "", 2.0),
      event(T::kStabilityChange, "", 2.0, cont::Criticality::kLimitPoint),  // that depth turn
      event(T::kMonitorMin, "force_N", 3.0),
      event(T::kStabilityChange, "", 4.0, cont::Criticality::kBifurcation),
      event(T::kInflection, "force_N", 4.5)};
  CriticalPoints out;
  collect_event_points(events, 0, out);
  ASSERT_EQ(out.limit_points.size(), 3u);
  EXPECT_EQ(out.limit_points[0].kind, CriticalKind::kForceMax);
  EXPECT_EQ(out.limit_points[1].kind, CriticalKind::kDepthTurn);
  EXPECT_EQ(out.limit_points[2].kind, CriticalKind::kForceMin);
  EXPECT_DOUBLE_EQ(out.limit_points[2].force, 30.0);
  ASSERT_EQ(out.bifurcations.size(), 1u);
  EXPECT_DOUBLE_EQ(out.bifurcations[0].depth, 4.0);
}

// The coarse quarter cap, [0/90]2S, `kinematics`, pseudo-arclength to `depth_max` (or natural).
CaseFile small_cap(const std::string& kinematics, double depth_max) {
  CaseFile c = testing::coarse_cap_case(kinematics, "[0/90]2S", "quarter", 1.25, 2.5);
  c.path.depth_max = depth_max;
  c.path.step = 0.1;
  c.path.step_min = 1e-4;
  c.path.step_max = 0.5;
  return c;
}

// The force at depth h exactly: a natural run of the case to h (ten equal steps) - nothing
// interpolated - or, with linear kinematics, the fast path at h.
double force_at(const std::string& kinematics, double h) {
  CaseFile c = small_cap(kinematics, h);
  c.path.method = PathMethod::kNatural;
  c.path.step = h / 10;
  c.path.step_min = h / 1e4;
  c.path.step_max = h / 10;
  c.path.depths = {h};
  IndentationSetup s(c, 1);
  PathControl control;
  control.critical_points = false;
  const PathResult r = run_indentation_path(s, {}, control);
  EXPECT_TRUE(r.completed) << r.reason;
  EXPECT_NEAR(r.points.back().state.depth, h, 1e-12);
  return r.points.back().state.force;
}

TEST(CriticalPoints, PaperCapOnsetAgreesWithBisectionOfNaturalSolves) {
  IndentationSetup s(small_cap("nonlinear", 3.0), 1);
  const PathResult r = run_indentation_path(s);
  ASSERT_TRUE(r.completed) << r.reason;
  const CriticalPoints& c = r.critical;
  ASSERT_EQ(c.onset_status, OnsetStatus::kFound);
  const double f = c.nonlinearity_fraction;
  const auto deviation = [&](double h) {
    const double t_lin = force_at("linear", h);
    return std::abs(force_at("nonlinear", h) - t_lin) / t_lin - f;
  };
  double lo = c.onset->depth - 0.1, hi = c.onset->depth + 0.1;
  ASSERT_LT(deviation(lo), 0);
  ASSERT_GE(deviation(hi), 0);
  while (hi - lo > 1e-6) {
    const double mid = 0.5 * (lo + hi);
    (deviation(mid) < 0 ? lo : hi) = mid;
  }
  const double bisected = 0.5 * (lo + hi);
  EXPECT_LE(std::abs(c.onset->depth - bisected), c.onset->accuracy + 1e-6)
      << "reported " << c.onset->depth << " +- " << c.onset->accuracy << ", bisected " << bisected;
  EXPECT_NEAR(c.onset->linear_force, force_at("linear", c.onset->depth),
              1e-8 * c.onset->linear_force);
  // The linear path has no onset, and its T(h) no inflection (straight on each contact set).
  IndentationSetup lin(small_cap("linear", 3.0), 1);
  const PathResult rl = run_indentation_path(lin);
  EXPECT_EQ(rl.critical.onset_status, OnsetStatus::kLinearKinematics);
  EXPECT_TRUE(rl.critical.inflections.empty());
  EXPECT_TRUE(rl.critical.limit_points.empty());
}

// The onset's trial solves start from the solved states on either side of the trial depth: the
// force is the natural run's (to the corrector's tolerance), a depth is not solved twice, and a
// trial between the bracket's ends takes fewer Newton iterations than the run's step across it,
// one next to a solved trial at most two.
TEST(OnsetWatch, TrialSolvesReuseSolvedStatesAndAgreeWithNaturalSolves) {
  IndentationSetup s(small_cap("nonlinear", 3.0), 1);
  const std::shared_ptr<OnsetWatch> watch = watch_onset(s);
  ASSERT_TRUE(watch);
  EXPECT_FALSE(watch->bracket().has_value());  // nothing crossed before the run
  PathControl control;
  control.critical_points = false;
  const PathResult r = run_indentation_path(s, watching(watch, {}), control);
  ASSERT_TRUE(r.completed) << r.reason;
  const auto bracket = watch->bracket();
  ASSERT_TRUE(bracket.has_value());
  const auto [from, to] = *bracket;
  ASSERT_LT(from, to);
  int step_iterations = 0;  // the run's corrector from the bracket's start to its end
  for (const PathPoint& p : r.points)
    if (p.state.depth == to) step_iterations = p.iterations;
  double t = 0;
  EXPECT_FALSE(watch->solve_force(s, from + 1e-3, 0.5 * (from + to), t));  // not its bracket
  EXPECT_EQ(watch->trial_solves(), 0);
  const double h = from + 0.5 * (to - from);
  ASSERT_TRUE(watch->solve_force(s, from, h, t));
  EXPECT_NEAR(t, force_at("nonlinear", h), 1e-8 * std::abs(t));
  double again = 0;
  ASSERT_TRUE(watch->solve_force(s, from, h, again));
  EXPECT_EQ(again, t);
  EXPECT_EQ(watch->trial_solves(), 1);
  const int before = watch->trial_iterations();
  EXPECT_LT(before, step_iterations);
  const double near = h + 1e-3 * (to - from);
  ASSERT_TRUE(watch->solve_force(s, from, near, t));
  EXPECT_EQ(watch->trial_solves(), 2);
  EXPECT_LE(watch->trial_iterations() - before, 2);
  EXPECT_NEAR(t, force_at("nonlinear", near), 1e-8 * std::abs(t));
}

// Once the run has crossed, the twin's factor is freed for the rest of the run; a linear force
// asked after it (the onset search's) is that of a twin that kept its factor, to round-off:
// refactored where a new Schur column needs it, else from the kept columns (computed in blocks
// of other sizes than the kept twin's, so not to the last bit).
TEST(OnsetWatch, FreesTheTwinsFactorOnceCrossedAndAnswersTheSameAfter) {
  IndentationSetup s(small_cap("nonlinear", 3.0), 1);
  const std::shared_ptr<OnsetWatch> watch = watch_onset(s);
  const std::shared_ptr<OnsetWatch> kept = watch_onset(s);  // fed nothing: keeps its factor
  ASSERT_TRUE(watch && kept);
  EXPECT_TRUE(watch->holds_twin_factor());
  PathControl control;
  control.critical_points = false;
  bool held_before_crossing = true;
  const auto check = [&](const PathPoint&, const cont::Vector&) {
    if (!watch->bracket())
      held_before_crossing = held_before_crossing && watch->holds_twin_factor();
    return true;
  };
  const PathResult r = run_indentation_path(s, watching(watch, check), control);
  ASSERT_TRUE(r.completed) << r.reason;
  const auto bracket = watch->bracket();
  ASSERT_TRUE(bracket.has_value());
  EXPECT_TRUE(held_before_crossing);
  EXPECT_FALSE(watch->holds_twin_factor());
  const auto [from, to] = *bracket;
  // Inside the bracket (the search's depths) and far beyond it (new columns: refactored).
  for (double h : {from + 0.3 * (to - from), to, 2.5}) {
    const double freed = watch->linear_force(h);
    EXPECT_NEAR(freed, kept->linear_force(h), 1e-13 * std::abs(freed)) << h;
    EXPECT_NEAR(freed, force_at("linear", h), 1e-9 * std::abs(freed)) << h;
  }
  EXPECT_TRUE(watch->holds_twin_factor());  // 2.5 mm needed new columns
}

// A resumed run feeds the watch from its checkpoint's point on: the passage's start and any
// bracket are behind it, so the watch keeps none and solves no linear twin (at the resumed depth
// that costs a solve per contact node: over ten minutes on the 1e6-unknown cap). Fed the same
// points from the start, it brackets the onset.
TEST(OnsetWatch, ResumedRunKeepsNoBracketAndSolvesNoTwin) {
  IndentationSetup s(small_cap("nonlinear", 3.0), 1);
  std::vector<std::pair<PathPoint, cont::Vector>> fed;
  PathControl control;
  control.critical_points = false;
  const PathResult r = run_indentation_path(
      s,
      [&](const PathPoint& p, const cont::Vector& z) {
        fed.emplace_back(p, z);
        return true;
      },
      control);
  ASSERT_TRUE(r.completed) << r.reason;
  ASSERT_GT(fed.size(), 4u);
  const std::shared_ptr<OnsetWatch> whole = watch_onset(s);
  for (const auto& [p, z] : fed) whole->add(p, z);
  ASSERT_TRUE(whole->bracket().has_value());
  EXPECT_GT(whole->linear_solves(), 0);
  const std::size_t resumed_at = fed.size() / 2;
  ASSERT_GT(fed[resumed_at].first.index, 0);
  const std::shared_ptr<OnsetWatch> resumed = watch_onset(s);
  for (std::size_t i = resumed_at; i < fed.size(); ++i) resumed->add(fed[i].first, fed[i].second);
  EXPECT_FALSE(resumed->bracket().has_value());
  EXPECT_EQ(resumed->linear_solves(), 0);
}

// The first step out of first touch starts from the linear twin's state at its depth
// (IndentationProblem::set_first_step_start): the step converges to the same point as a natural
// solve at that depth, in fewer Newton iterations than from the tangent at first touch (which
// sees the one touching node); the onset found is the same. The twin's state is not offered for
// any other step, nor once the watch has crossed.
TEST(OnsetWatch, FirstStepStartsFromTheTwinsStateAndConvergesFaster) {
  IndentationSetup with(small_cap("nonlinear", 1.0), 1);
  std::vector<std::pair<PathPoint, cont::Vector>> fed;
  const PathResult a = run_indentation_path(with, [&](const PathPoint& pt, const cont::Vector& z) {
    fed.emplace_back(pt, z);
    return true;
  });  // with its own watch: the twin's start
  IndentationSetup without(small_cap("nonlinear", 1.0), 1);
  PathControl control;
  control.critical_points = false;  // no watch: the predictor's start
  const PathResult b = run_indentation_path(without, {}, control);
  ASSERT_TRUE(a.completed && b.completed) << a.reason << b.reason;
  const PathPoint& first = a.points.at(1);
  EXPECT_LT(first.iterations, b.points.at(1).iterations);
  EXPECT_NEAR(first.state.force, force_at("nonlinear", first.state.depth),
              1e-8 * first.state.force);
  EXPECT_NEAR(a.points.back().state.force, b.points.back().state.force,
              1e-8 * b.points.back().state.force);

  IndentationSetup s(small_cap("nonlinear", 1.0), 1);
  const std::shared_ptr<OnsetWatch> watch = watch_onset(s);
  IndentationProblem& p = *s.problem;
  int offered = 0;
  const IndentationProblem::FirstStepStart twin = first_step_from_twin(watch, p);
  p.set_first_step_start([&](double h) {
    ++offered;
    return twin(h);
  });
  const cont::Vector zero = p.initial_point();
  const cont::Vector start = p.corrector_start(zero, 0.0, 0.1);
  ASSERT_EQ(start.size(), p.size());
  EXPECT_NEAR(p.indenter_force(start), watch->linear_force(0.1), 1e-9 * watch->linear_force(0.1));
  EXPECT_EQ(p.corrector_start(start, 0.1, 0.2).size(), 0);  // not from first touch
  EXPECT_EQ(offered, 1);
  for (const auto& [pt, z] : fed) watch->add(pt, z);
  ASSERT_TRUE(watch->bracket().has_value());
  EXPECT_EQ(watch->linear_state(0.1, p).size(), 0);  // crossed: the twin's factor is freed
}

// A run the user stopped (Ctrl-C) reports the onset from its points, without the re-solves that
// locate it to 1e-9 mm (each costs a step: minutes on a 1e6-unknown cap); the full run's located
// onset lies within the stopped run's stated accuracy.
TEST(CriticalPoints, StoppedRunTakesTheOnsetFromItsPointsWithoutReSolves) {
  IndentationSetup full_setup(small_cap("nonlinear", 3.0), 1);
  const PathResult full = run_indentation_path(full_setup);
  ASSERT_EQ(full.critical.onset_status, OnsetStatus::kFound);
  IndentationSetup s(small_cap("nonlinear", 3.0), 1);
  const PathResult r = run_indentation_path(
      s, [&](const PathPoint& p, const cont::Vector&) { return p.state.depth < 2.0; });
  ASSERT_EQ(r.status, RunStatus::kStopped);
  ASSERT_EQ(r.critical.onset_status, OnsetStatus::kFound);
  const CriticalPoint& onset = *r.critical.onset;
  EXPECT_GT(onset.accuracy, 1e-6);  // the points' interpolation, not a re-solved bracket
  EXPECT_LT(full.critical.onset->accuracy, 1e-6);
  EXPECT_LE(std::abs(onset.depth - full.critical.onset->depth), onset.accuracy);
}

}  // namespace
}  // namespace si
