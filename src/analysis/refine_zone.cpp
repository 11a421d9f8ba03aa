#include "analysis/refine_zone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace si {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A refined zone of fewer elements than this across its radius grades too steeply into the far
// field for the bending around the contact.
constexpr double kMinimumElements = 4;

// How far a circle of radius rho rises above its lowest point at plan distance r from it.
double circle_rise(double rho, double r) {
  return r < rho ? rho - std::sqrt(rho * rho - r * r) : kInfinity;
}

// The indenter's surface height above its tip at plan distance r along its widest direction, and
// that direction's plan extent (beyond it the indenter has no surface facing the shell).
struct Profile {
  double extent = 0;
  double rise(const IndenterSpec& s, double r) const {
    if (r > extent) return kInfinity;
    switch (s.shape) {
      case IndenterShape::kSphere:
        return circle_rise(s.radius, r);
      case IndenterShape::kFlatPunch: {
        const double flat = s.radius - s.edge_radius;
        return r <= flat ? 0 : circle_rise(s.edge_radius, r - flat);
      }
      case IndenterShape::kCylinder:
        return 0;  // along its axis: in contact over its length at once
      case IndenterShape::kSuperquadric: {
        // Along x (|x/A|^(2/e1) + |z/c|^(2/e1) = 1): the height above the tip where x = r.
        const double q = 1 - std::pow(r / extent, 2 / s.e1);
        return s.c * (1 - std::pow(std::max(q, 0.0), s.e1 / 2));
      }
    }
    return kInfinity;
  }
};

Profile profile_of(const IndenterSpec& s) {
  switch (s.shape) {
    case IndenterShape::kSphere:
    case IndenterShape::kFlatPunch:
      return {s.radius};
    case IndenterShape::kCylinder:
      return {0.5 * s.length};
    case IndenterShape::kSuperquadric:
      // The plan section lies within max(a, b) for a rounded superellipse (e2 >= 1) and within
      // its bounding box's half diagonal for a boxy one.
      return {s.e2 < 1 ? std::hypot(s.a, s.b) : std::max(s.a, s.b)};
  }
  return {};
}

// How far the contact face falls below its apex tangent plane at plan distance r, along its
// flattest direction: a cap's face is a sphere; plates and a cylindrical panel's axis are flat.
double face_drop(const IndentationCase& c, double r) {
  if (c.shell.type != ShellType::kSphericalCap) return 0;
  return circle_rise(c.shell.radius + contact_face_offset(c), r);
}

}  // namespace

double indenter_reach(const IndentationCase& c, double depth) {
  const Profile p = profile_of(c.indenter);
  const auto gap = [&](double r) { return p.rise(c.indenter, r) + face_drop(c, r); };
  if (!(depth > 0)) return 0;
  if (gap(p.extent) <= depth) return p.extent;
  // gap(r) rises from 0 at r = 0: bisection for gap(r) = depth.
  double lo = 0, hi = p.extent;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) <= depth ? lo : hi) = mid;
  }
  return lo;
}

IndentationCase with_refine_zone(IndentationCase c) {
  if (c.mesh.refine_radius || !c.mesh.file.empty()) return c;
  c.mesh.refine_radius =
      std::max(indenter_reach(c, c.path.depth_max), kMinimumElements * c.mesh.size_apex);
  return c;
}

}  // namespace si
