#include "section/laminate.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "material/ply_rotation.hpp"

namespace si {

Matrix6d Ply::stiffness_yu() const {
  return ply_stiffness_yu(material.stiffness(), angle_deg);
}

double Laminate::thickness() const {
  double h = 0;
  for (const auto& p : plies) h += p.thickness;
  return h;
}

std::vector<double> Laminate::interfaces() const {
  std::vector<double> z{-0.5 * thickness()};
  for (const auto& p : plies) z.push_back(z.back() + p.thickness);
  z.back() = 0.5 * thickness();  // exact top face despite round-off in the running sum
  return z;
}

int Laminate::ply_at(double x3) const {
  const auto z = interfaces();
  const int n = static_cast<int>(plies.size());
  for (int k = 0; k < n; ++k)
    if (x3 < z[k + 1]) return k;
  return n - 1;
}

void Laminate::validate() const {
  if (plies.empty()) throw_input("the laminate has no plies");
  for (size_t k = 0; k < plies.size(); ++k) {
    const double t = plies[k].thickness;
    if (!(t > 0.0) || !std::isfinite(t)) {
      std::ostringstream os;
      os << "ply " << k + 1 << " thickness must be positive (got " << t << " mm)";
      throw_input(os.str());
    }
  }
  const double h = thickness();
  if (std::abs(reference_offset) > 0.5 * h * (1 + 1e-12)) {
    std::ostringstream os;
    os << "reference surface offset " << reference_offset
       << " mm lies outside the laminate (|offset| <= h/2 = " << 0.5 * h << " mm)";
    throw_input(os.str());
  }
}

}  // namespace si
