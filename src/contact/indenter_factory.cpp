#include "contact/indenter_factory.hpp"

#include <cmath>
#include <sstream>

#include "contact/cylinder_indenter.hpp"
#include "contact/flat_punch_indenter.hpp"
#include "contact/sphere_indenter.hpp"
#include "contact/superquadric_indenter.hpp"
#include "core/error.hpp"

namespace si {
namespace {

std::string text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

void require(bool ok, const std::string& key, double value, const std::string& reason) {
  if (!ok) throw_input(reason, Where{"", "indenter." + key, text(value), 0});
}

void require_positive(const std::string& key, double value) {
  require(value > 0.0, key, value, "must be positive");
}

void require_exponent(const std::string& key, double value) {
  require(value > 0.0 && value <= 2.0, key, value,
          "a superquadric exponent must lie in (0, 2] (convex shapes)");
}

}  // namespace

std::unique_ptr<Indenter> make_indenter(const IndenterSpec& spec, const IndenterPose& pose) {
  const double dn = pose.direction.norm();
  require(dn > 0.0 && std::isfinite(dn), "direction", dn,
          "the direction of travel must be nonzero");
  IndenterPose unit = pose;
  unit.direction /= dn;
  switch (spec.shape) {
    case IndenterShape::kSphere:
      require_positive("radius", spec.radius);
      return std::make_unique<SphereIndenter>(spec.radius, unit);
    case IndenterShape::kSuperquadric:
      require_positive("a", spec.a);
      require_positive("b", spec.b);
      require_positive("c", spec.c);
      require_exponent("e1", spec.e1);
      require_exponent("e2", spec.e2);
      return std::make_unique<SuperquadricIndenter>(
          SuperquadricShape{spec.a, spec.b, spec.c, spec.e1, spec.e2}, unit);
    case IndenterShape::kFlatPunch:
      require_positive("radius", spec.radius);
      require(spec.edge_radius >= 0.0 && spec.edge_radius < spec.radius, "edge_radius",
              spec.edge_radius, "must lie in [0, radius)");
      return std::make_unique<FlatPunchIndenter>(spec.radius, spec.edge_radius, unit);
    case IndenterShape::kCylinder: {
      require_positive("radius", spec.radius);
      require(spec.length >= 0.0, "length", spec.length, "must be >= 0 (0 = infinite)");
      const double along = std::abs(pose.axis.normalized().dot(unit.direction));
      require(pose.axis.norm() > 0.0 && along < 1.0 - 1e-8, "axis", along,
              "the cylinder axis must not be parallel to the direction of travel");
      return std::make_unique<CylinderIndenter>(spec.radius, spec.length, unit);
    }
  }
  throw_input("unknown indenter shape", Where{"", "indenter.shape", "", 0});
}

}  // namespace si
