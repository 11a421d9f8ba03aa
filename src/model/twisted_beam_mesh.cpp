#include "model/twisted_beam_mesh.hpp"

#include <cmath>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "model/mesh_quality.hpp"
#include "model/structured_grid.hpp"

namespace si {
namespace {}  // namespace

Mesh twisted_beam_mesh(const TwistedBeamSpec& spec) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!positive(spec.length))
    throw_input("must be positive", {"", "length", std::to_string(spec.length)});
  if (!positive(spec.width))
    throw_input("must be positive", {"", "width", std::to_string(spec.width)});
  if (!std::isfinite(spec.twist_deg)) {
    throw_input("must be finite", {"", "twist_deg", std::to_string(spec.twist_deg)});
  }
  if (spec.n_length < 1)
    throw_input("must be positive", {"", "n_length", std::to_string(spec.n_length)});
  if (spec.n_width < 1)
    throw_input("must be positive", {"", "n_width", std::to_string(spec.n_width)});

  const double rate = spec.twist_deg * kPi / 180 / spec.length;  // a'(x)
  const auto x_at = [&](int i) {
    return i == spec.n_length ? spec.length : spec.length * i / spec.n_length;
  };
  const auto w_at = [&](int j) {
    return spec.width * (j / static_cast<double>(spec.n_width) - 0.5);
  };
  // u = x, v = w: p_x cross p_w = (-w a', -sin a, cos a).
  Mesh mesh = structured_grid(spec.n_length, spec.n_width, [&](int i, int j) {
    const double a = rate * x_at(i), w = w_at(j);
    return Vector3d(x_at(i), w * std::cos(a), w * std::sin(a));
  });
  for (int j = 0; j <= spec.n_width; ++j) {
    for (int i = 0; i <= spec.n_length; ++i) {
      const double a = rate * x_at(i), w = w_at(j);
      mesh.directors.push_back(Vector3d(-w * rate, -std::sin(a), std::cos(a)).normalized());
    }
  }
  set_node_set(mesh, "root", nodes_where(mesh, [](const Vector3d& p) { return p.x() == 0; }));
  set_node_set(mesh, "tip",
               nodes_where(mesh, [&](const Vector3d& p) { return p.x() == spec.length; }));
  check_mesh(mesh);
  return mesh;
}

}  // namespace si
