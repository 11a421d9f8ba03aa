#include "analysis/critical_points.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "analysis/grid_features.hpp"
#include "analysis/onset_watch.hpp"
#include "analysis/path_columns.hpp"
#include "analysis/stiffness_wells.hpp"
#include "continuation/brent_root.hpp"
#include "continuation/curve_features.hpp"

namespace si {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
// The onset's search on solved points stops once the deviation from the linear response is
// within this of its fraction: ten times the deviation's own noise (the corrector's 1e-10
// relative force tolerance), and one solve fewer than the 1e-9 mm bracket on the main job.
constexpr double kDeviationTolerance = 1e-9;

double slope_at(const PathPoint& p, int force_slope) {
  return force_slope >= 0 && force_slope < p.depth_slopes.size() ? p.depth_slopes[force_slope]
                                                                 : kNan;
}

// The points of the path's first passage of the depth: up to where the depth first decreases
// (a snap-back; the onset and the inflections are properties of T as a function of h).
int first_passage(const std::vector<PathPoint>& points) {
  int n = std::min<int>(1, static_cast<int>(points.size()));
  while (n < static_cast<int>(points.size()) && points[n].state.depth > points[n - 1].state.depth)
    ++n;
  return n;
}

// T at depth d between a and b: cubic Hermite with the exact slopes when `hermite`, else linear.
double force_between(const PathPoint& a, const PathPoint& b, double d, int force_slope,
                     bool hermite) {
  const double dd = b.state.depth - a.state.depth, t = (d - a.state.depth) / dd;
  if (!hermite) return (1 - t) * a.state.force + t * b.state.force;
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  return h00 * a.state.force + h10 * dd * slope_at(a, force_slope) + h01 * b.state.force +
         h11 * dd * slope_at(b, force_slope);
}

// The root of r in [lo, hi], r(lo) < 0 <= r(hi), by Brent's method (continuation/brent_root.hpp)
// until the bracket is `tolerance` (mm) wide, or |r| <= value_tolerance, or r vanishes;
// `accuracy` = the final bracket, or once within the value, the secant's distance to the root
// (never more than the bracket). r is NaN where it cannot be evaluated: then NaN.
double root_between(const std::function<double(double)>& r, double lo, double hi, double rlo,
                    double rhi, double tolerance, double value_tolerance, double& accuracy) {
  bool failed = false;
  const auto value = [&](double h) {
    const double v = r(h);
    failed = failed || std::isnan(v);
    return v;
  };
  const cont::RootSearch search{tolerance, value_tolerance, 200};
  const cont::RootBracket<double> b = cont::brent_root(value, lo, hi, rlo, rhi, search);
  accuracy = b.accuracy(search);
  return failed ? std::nan("") : b.best.x;
}

// The inflection indicator's curve T(h) at interior point i: T' exact where the points carry it
// (the derivative of T'' then by three-point differences of the slopes), else both derivatives by
// differences of the values; the error of T'' from the points' accuracy.
cont::Point force_point(const std::vector<PathPoint>& pts, int i, int force_slope,
                        double force_magnitude, double slope_magnitude) {
  const DifferenceWeights w = difference_weights(pts[i].state.depth - pts[i - 1].state.depth,
                                                 pts[i + 1].state.depth - pts[i].state.depth);
  const Eigen::Vector3d t(pts[i - 1].state.force, pts[i].state.force, pts[i + 1].state.force);
  const Eigen::Vector3d s(slope_at(pts[i - 1], force_slope), slope_at(pts[i], force_slope),
                          slope_at(pts[i + 1], force_slope));
  cont::Point p;
  p.p = pts[i].state.depth;
  p.tangent_p = 1;
  p.parameter_curvature = 0;
  p.parameter_curvature_error = 0;
  p.monitors = Eigen::VectorXd::Constant(1, t(1));
  if (s.allFinite()) {
    p.monitor_slopes = Eigen::VectorXd::Constant(1, s(1));
    p.monitor_curvatures = Eigen::VectorXd::Constant(1, w.first.dot(s));
    p.monitor_curvature_errors =
        Eigen::VectorXd::Constant(1, w.first.cwiseAbs().sum() * kPointAccuracy * slope_magnitude);
  } else {
    p.monitor_slopes = Eigen::VectorXd::Constant(1, w.first.dot(t));
    p.monitor_curvatures = Eigen::VectorXd::Constant(1, w.second.dot(t));
    p.monitor_curvature_errors =
        Eigen::VectorXd::Constant(1, w.second.cwiseAbs().sum() * kPointAccuracy * force_magnitude);
  }
  return p;
}

// The well's relative depth: the stiffness must rise by 5 % of its extreme value on both sides
// (the onset's default fraction; larger than the jumps of a node entering contact on the cap's
// meshes of 1.25 mm and finer, docs/critical-points.md).
constexpr double kStiffnessWellFraction = 0.05;

bool has_slopes(const PathPoint& a, const PathPoint& b, int force_slope) {
  return std::isfinite(slope_at(a, force_slope)) && std::isfinite(slope_at(b, force_slope));
}

// The index k of the segment (k - 1, k) of the points holding depth d (1 <= k < size).
int segment_holding(const std::vector<PathPoint>& points, double d) {
  int k = 1;
  while (k + 1 < static_cast<int>(points.size()) && points[k].state.depth < d) ++k;
  return k;
}

// Every point with depth in [from, to] presses the same nodes.
bool one_contact_set(const std::vector<PathPoint>& points, double from, double to) {
  std::optional<std::vector<int>> set;
  for (const PathPoint& p : points) {
    if (p.state.depth < from || p.state.depth > to) continue;
    const std::vector<int> nodes = pressing_nodes(p.state);
    if (set && nodes != *set) return false;
    set = nodes;
  }
  return true;
}

// dT/dh at the points (their exact slopes), or where any point carries none, the secants of
// the segments at their mid-depths.
std::vector<StiffnessSample> stiffness_samples(const std::vector<PathPoint>& points,
                                               int force_slope) {
  std::vector<StiffnessSample> samples;
  const bool exact = std::all_of(points.begin(), points.end(), [&](const PathPoint& p) {
    return std::isfinite(slope_at(p, force_slope));
  });
  if (exact) {
    for (const PathPoint& p : points) samples.push_back({p.state.depth, slope_at(p, force_slope)});
    return samples;
  }
  for (std::size_t i = 1; i < points.size(); ++i) {
    const IndentationState &a = points[i - 1].state, &b = points[i].state;
    samples.push_back({0.5 * (a.depth + b.depth), (b.force - a.force) / (b.depth - a.depth)});
  }
  return samples;
}

// The sign changes of d2T/dh2 the curve-feature rules resolve between two points of one
// contact set (grid_features.hpp), with the force and stiffness on the segment holding each.
std::vector<CriticalPoint> local_inflections(const std::vector<PathPoint>& points,
                                             int force_slope) {
  cont::CurveScales scales;
  double force_magnitude = 0, slope_magnitude = 0;
  for (const PathPoint& pt : points) {
    cont::Point p;
    p.p = pt.state.depth;
    p.monitors = Eigen::VectorXd::Constant(1, pt.state.force);
    scales.include(p);
    force_magnitude = std::max(force_magnitude, std::abs(pt.state.force));
    const double s = slope_at(pt, force_slope);
    if (std::isfinite(s)) slope_magnitude = std::max(slope_magnitude, std::abs(s));
  }
  const cont::Indicator extremum{cont::EventType::kSlopeMin, 0, -1};
  std::vector<CriticalPoint> found;
  for (const cont::Event& e : grid_features(
           points, extremum,
           [&](int i) {
             return force_point(points, i, force_slope, force_magnitude, slope_magnitude);
           },
           scales)) {
    CriticalPoint c;
    c.kind = e.type == cont::EventType::kSlopeMin ? CriticalKind::kStiffnessMin
                                                  : CriticalKind::kStiffnessMax;
    c.depth = e.p;
    c.accuracy = e.accuracy;
    // The force and the stiffness on the segment of points holding the depth (the slopes
    // linearly, or the segment's secant where the points carry none).
    const int k = segment_holding(points, e.p);
    const PathPoint &a = points[k - 1], &b = points[k];
    const double t = (e.p - a.state.depth) / (b.state.depth - a.state.depth);
    const bool slopes = has_slopes(a, b, force_slope);
    c.force = force_between(a, b, e.p, force_slope, slopes);
    c.stiffness = slopes ? (1 - t) * slope_at(a, force_slope) + t * slope_at(b, force_slope)
                         : (b.state.force - a.state.force) / (b.state.depth - a.state.depth);
    found.push_back(c);
  }
  return found;
}

CriticalPoint event_point(CriticalKind kind, const cont::Event& e, int force) {
  CriticalPoint c;
  c.kind = kind;
  c.depth = e.p;
  c.force = force >= 0 && force < e.monitors.size() ? e.monitors[force] : kNan;
  c.accuracy = e.accuracy;
  c.located = e.located;
  return c;
}

}  // namespace

void find_nonlinearity_onset(const std::vector<PathPoint>& points, int force_slope,
                             const LinearForce& linear, double fraction, CriticalPoints& out,
                             const ExactForce& exact) {
  out.nonlinearity_fraction = fraction;
  const int n = first_passage(points);
  if (n < 2) {
    out.onset_status = OnsetStatus::kTooFewPoints;
    return;
  }
  // r(h) = |T - T_lin| / |T_lin| - f; at the start (h = 0, no force) the limit of the ratio is
  // 0: both responses start with the same linear stiffness.
  const auto deviation = [&](double h, double t) {
    if (!(h > 0)) return -fraction;
    const double t_lin = linear(h);
    return std::abs(t - t_lin) / std::abs(t_lin) - fraction;
  };
  out.onset_status = OnsetStatus::kNone;
  out.max_deviation = 0;
  double r_previous = deviation(points[0].state.depth, points[0].state.force);
  for (int i = 1; i < n; ++i) {
    const PathPoint &a = points[i - 1], &b = points[i];
    const double r = deviation(b.state.depth, b.state.force);
    out.max_deviation = std::max(out.max_deviation, r + fraction);
    if (r < 0) {
      r_previous = r;
      continue;
    }
    const bool slopes = has_slopes(a, b, force_slope);
    const auto root = [&](bool hermite, double& width) {
      return root_between(
          [&](double h) { return deviation(h, force_between(a, b, h, force_slope, hermite)); },
          a.state.depth, b.state.depth, r_previous, r, 1e-12 * (1 + b.state.depth), 0.0, width);
    };
    CriticalPoint c;
    c.kind = CriticalKind::kNonlinearityOnset;
    double width = 0;
    // Solved: the force at each trial depth by the run's own corrector.
    const double solved =
        !exact ? std::nan("")
               : root_between(
                     [&](double h) {
                       double t = 0;
                       return exact(a.state.depth, h, t) ? deviation(h, t) : std::nan("");
                     },
                     a.state.depth, b.state.depth, r_previous, r, 1e-9, kDeviationTolerance, width);
    if (std::isfinite(solved)) {
      c.depth = solved;
      c.located = true;
      c.accuracy = std::max(width, 1e-12);
      exact(a.state.depth, solved, c.force);
    } else {
      const double secant = root(false, width);
      c.depth = slopes ? root(true, width) : secant;
      c.located = slopes && pressing_nodes(a.state) == pressing_nodes(b.state);
      c.accuracy = c.located ? std::max(std::abs(c.depth - secant), 1e-12 * (1 + c.depth))
                             : b.state.depth - a.state.depth;
      c.force = force_between(a, b, c.depth, force_slope, slopes);
    }
    c.linear_force = linear(c.depth);
    out.onset = c;
    out.onset_status = OnsetStatus::kFound;
    return;
  }
}

std::vector<CriticalPoint> force_inflections(const std::vector<PathPoint>& all, int force_slope) {
  const std::vector<PathPoint> points(all.begin(), all.begin() + first_passage(all));
  const std::vector<CriticalPoint> local = local_inflections(points, force_slope);
  const std::vector<StiffnessSample> samples = stiffness_samples(points, force_slope);
  std::vector<CriticalPoint> found;
  for (const StiffnessWell& well : stiffness_wells(samples, kStiffnessWellFraction)) {
    // A well on one contact set is a smooth curve: its sign change of d2T/dh2 is exact there.
    std::vector<CriticalPoint> inside;
    for (const CriticalPoint& c : local)
      if (c.kind == well.kind && c.depth > well.from && c.depth < well.to) inside.push_back(c);
    if (inside.size() == 1 && one_contact_set(points, well.from, well.to)) {
      found.push_back(inside.front());
      continue;
    }
    const std::optional<StiffnessVertex> v = fitted_vertex(samples, well);
    if (!v) continue;
    CriticalPoint c;
    c.kind = well.kind;
    c.depth = v->depth;
    c.accuracy = v->accuracy;
    c.stiffness = v->stiffness;
    const int k = segment_holding(points, v->depth);
    c.force = force_between(points[k - 1], points[k], v->depth, force_slope,
                            has_slopes(points[k - 1], points[k], force_slope));
    found.push_back(c);
  }
  return found;
}

void collect_event_points(const std::vector<cont::Event>& events, int force, CriticalPoints& out) {
  const std::string force_name = column_name(PathColumn::kForce);
  for (const cont::Event& e : events) {
    if (e.type == cont::EventType::kLimitPoint)
      out.limit_points.push_back(event_point(CriticalKind::kDepthTurn, e, force));
    else if (e.type == cont::EventType::kMonitorMax && e.monitor == force_name)
      out.limit_points.push_back(event_point(CriticalKind::kForceMax, e, force));
    else if (e.type == cont::EventType::kMonitorMin && e.monitor == force_name)
      out.limit_points.push_back(event_point(CriticalKind::kForceMin, e, force));
    else if (e.type == cont::EventType::kBifurcation ||
             (e.type == cont::EventType::kStabilityChange &&
              e.criticality == cont::Criticality::kBifurcation))
      out.bifurcations.push_back(event_point(CriticalKind::kBifurcation, e, force));
  }
}

namespace {

int position_of(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

// The linear twin is solved by the linear fast path, which knows the indenter's rows only.
bool has_onset(const IndentationSetup& setup) {
  return setup.model.kinematics != Kinematics::kLinear &&
         setup.problem->local_law().kind == LocalLawKind::kNone && !setup.problem->support_frame();
}

}  // namespace

std::shared_ptr<OnsetWatch> watch_onset(const IndentationSetup& setup) {
  return has_onset(setup) ? std::make_shared<OnsetWatch>(setup) : nullptr;
}

void watch_point(OnsetWatch& watch, const PathPoint& point, const cont::Vector& z) {
  watch.add(point, z);
}

CriticalPoints find_critical_points(IndentationSetup& setup, const PathResult& r,
                                    OnsetWatch* watch) {
  CriticalPoints out;
  out.nonlinearity_fraction = setup.spec.path.nonlinearity_fraction;
  out.stability = r.stability;
  // The points' depth slopes and the events' monitors are in the run's monitor order.
  const int force = position_of(r.monitor_names, column_name(PathColumn::kForce));
  if (setup.model.kinematics == Kinematics::kLinear) {
    out.onset_status = OnsetStatus::kLinearKinematics;
  } else if (setup.problem->support_frame()) {
    out.onset_status = OnsetStatus::kSupportFrame;
  } else if (!has_onset(setup)) {
    out.onset_status = OnsetStatus::kLocalLaw;
  } else {
    std::shared_ptr<OnsetWatch> own = watch ? nullptr : watch_onset(setup);
    OnsetWatch& w = watch ? *watch : *own;
    // The run's corrector at the trial depths, from the states the watch kept (where it fails,
    // the points are used). Not after a stop (Ctrl-C): each re-solve costs a step (about 100 s
    // on a 1e6-unknown cap), and the user asked for the results now.
    const bool stopped = r.status == RunStatus::kStopped;
    const ExactForce exact = [&](double from, double h, double& t) {
      return !stopped && w.solve_force(setup, from, h, t);
    };
    find_nonlinearity_onset(
        r.points, force, [&](double h) { return w.linear_force(h); }, out.nonlinearity_fraction,
        out, exact);
  }
  out.inflections = force_inflections(r.points, force);
  collect_event_points(r.events, force, out);
  return out;
}

PathCallback watching(const std::shared_ptr<OnsetWatch>& watch, const PathCallback& callback) {
  if (!watch) return callback;
  return [watch, callback](const PathPoint& p, const cont::Vector& z) {
    watch_point(*watch, p, z);
    return !callback || callback(p, z);
  };
}

IndentationProblem::FirstStepStart first_step_from_twin(const std::shared_ptr<OnsetWatch>& watch,
                                                        const IndentationProblem& problem) {
  if (!watch) return nullptr;
  return [watch, &problem](double h) { return watch->linear_state(h, problem); };
}

}  // namespace si
