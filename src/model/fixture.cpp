#include "model/fixture.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/units.hpp"

namespace si {
namespace {

// The plate's half extents in plan (largest |x|, |y| of its nodes).
Vector2d half_extent(const Mesh& mesh) {
  Vector2d e = Vector2d::Zero();
  for (const Vector3d& p : mesh.nodes) e = e.cwiseMax(p.head<2>().cwiseAbs());
  return e;
}

std::string length_text(double v) {
  return format_quantity(v, Dimension::kLength);
}

// Whether plan point p lies over the cut-out or opening (not on its edge), with tolerance tol.
bool in_opening(const FixtureSpec& f, const Vector2d& p, double tol) {
  switch (f.type) {
    case FixtureType::kAstmD7136:
      return std::abs(p.x()) < 0.5 * f.window_x - tol && std::abs(p.y()) < 0.5 * f.window_y - tol;
    case FixtureType::kAstmD6264Opening:
      return p.norm() < 0.5 * f.opening_diameter - tol;
    case FixtureType::kAstmD6264Backed:
    case FixtureType::kNone:
      break;
  }
  return false;
}

// Whether plan point p lies on the edge of the cut-out or opening.
bool on_opening_edge(const FixtureSpec& f, const Vector2d& p, double tol) {
  return !in_opening(f, p, tol) &&
         (f.type == FixtureType::kAstmD7136 || f.type == FixtureType::kAstmD6264Opening) &&
         in_opening(f, p, -tol);
}

void check_opening(const FixtureSpec& f, const std::string& file, const Vector2d& half) {
  if (f.type == FixtureType::kAstmD7136 &&
      !(0.5 * f.window_x < half.x() && 0.5 * f.window_y < half.y())) {
    std::ostringstream os;
    os << "the cut-out must lie inside the plate (" << length_text(2 * half.x()) << " x "
       << length_text(2 * half.y()) << ")";
    throw_input(os.str(), Where{file, "fixture.window",
                                length_text(f.window_x) + " x " + length_text(f.window_y), 0});
  }
  if (f.type == FixtureType::kAstmD6264Opening && !(0.5 * f.opening_diameter < half.minCoeff()))
    throw_input("the opening must lie inside the plate (its smaller side is " +
                    length_text(2 * half.minCoeff()) + ")",
                Where{file, "fixture.opening_diameter", length_text(f.opening_diameter), 0});
}

}  // namespace

std::vector<Vector2d> astm_d7136_clamps() {
  return {{50.0, 43.75}, {-50.0, 43.75}, {-50.0, -43.75}, {50.0, -43.75}};
}

std::vector<int> apply_fixture(const FixtureSpec& f, const std::string& file, Mesh& mesh,
                               std::vector<Support>& supports) {
  const Vector2d half = half_extent(mesh);
  check_opening(f, file, half);
  const double tol = 1e-6 * half.maxCoeff();
  // A quarter model holds the part x >= 0, y >= 0 (its nodes have no negative coordinate).
  const bool quarter = std::none_of(mesh.nodes.begin(), mesh.nodes.end(), [&](const Vector3d& p) {
    return p.x() < -tol || p.y() < -tol;
  });
  std::vector<int> frame, edge, clamps;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vector2d p = mesh.nodes[n].head<2>();
    if (!in_opening(f, p, tol)) frame.push_back(n);
    if (on_opening_edge(f, p, tol)) edge.push_back(n);
  }
  for (const Vector2d& tip : f.clamps) {
    std::ostringstream value;
    value << "[" << length_text(tip.x()) << ", " << length_text(tip.y()) << "]";
    const Where where{file, "fixture.clamps", value.str(), 0};
    if (std::abs(tip.x()) > half.x() + tol || std::abs(tip.y()) > half.y() + tol)
      throw_input("a clamp tip must lie on the plate", where);
    if (in_opening(f, tip, tol))
      throw_input("a clamp tip must lie on the frame, outside the cut-out or opening", where);
    if (quarter && (tip.x() < -tol || tip.y() < -tol)) continue;  // its mirror image is meshed
    int nearest = 0;
    for (int n = 1; n < mesh.num_nodes(); ++n)
      if ((mesh.nodes[n].head<2>() - tip).norm() < (mesh.nodes[nearest].head<2>() - tip).norm())
        nearest = n;
    clamps.push_back(nearest);
  }
  std::sort(clamps.begin(), clamps.end());
  clamps.erase(std::unique(clamps.begin(), clamps.end()), clamps.end());
  set_node_set(mesh, "frame", frame);
  set_node_set(mesh, "window_edge", edge);
  if (!clamps.empty()) {
    set_node_set(mesh, "clamps", clamps);
    supports.push_back({SupportKind::kFixedDofs, "clamps", -1, {2}});
  }
  return frame;
}

std::vector<double> with_station(std::vector<double> half, double at) {
  if (half.size() < 2 || !(at > 0 && at < half.back())) return half;
  const auto next = std::lower_bound(half.begin(), half.end(), at);
  const std::size_t k = static_cast<std::size_t>(next - half.begin());  // half[k-1] < at <= half[k]
  const double element = half[k] - half[k - 1];
  if (half[k] - at < element / 3 && k + 1 < half.size()) {
    half[k] = at;
  } else if (at - half[k - 1] < element / 3 && k > 1) {
    half[k - 1] = at;
  } else if (half[k] != at) {
    half.insert(half.begin() + static_cast<std::ptrdiff_t>(k), at);
  }
  return half;
}

}  // namespace si
