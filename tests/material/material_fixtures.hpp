// Materials shared by the material tests.
#pragma once

#include "core/linalg.hpp"
#include "material/material.hpp"

namespace si::testing {

// Nine distinct constants (MPa), so that a swapped index in the compliance or in the rotation
// shows up.
inline EngineeringConstants generic_constants() {
  EngineeringConstants c;
  c.E1 = 140000;
  c.E2 = 9000;
  c.E3 = 11000;
  c.G12 = 5000;
  c.G13 = 4500;
  c.G23 = 3200;
  c.nu12 = 0.28;
  c.nu13 = 0.31;
  c.nu23 = 0.42;
  return c;
}

inline double max_abs(const Matrix6d& m) {
  return m.cwiseAbs().maxCoeff();
}

}  // namespace si::testing
