// Sze's hinged cylindrical roof (K.Y. Sze, X.H. Liu, S.H. Lo, Finite Elements in Analysis and
// Design 40 (2004) 1551-1569, section 3.8; problem data: ../shared/benchmarks/nonlinear.md) as a
// load-controlled continuation problem: the quarter model with n x n mitc4 elements and the
// pseudo-arclength settings that trace it. Shared by the verification test
// (test_sze_hinged_roof.cpp) and the benchmark (bench/bench_roof.cpp).
#pragma once

#include <memory>
#include <vector>

#include "analysis/load_problem.hpp"
#include "continuation/settings.hpp"
#include "core/constants.hpp"
#include "model/cylindrical_panel_mesh.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si::verification {

// Sze et al. 2004 sec. 3.8: R = 2540, axial length 508, half-angle 0.1 rad, E = 3102.75,
// nu = 0.3, straight edges hinged, curved edges free, central point load P, Pmax = 3000.
constexpr double kRoofRadius = 2540, kRoofLength = 508, kRoofHalfAngleRad = 0.1;
constexpr double kRoofE = 3102.75, kRoofNu = 0.3, kRoofPmax = 3000;

// The straight edge hinged, the curved edge free, symmetry at the crown (x = 0) and at the axial
// mid-plane (y = 0).
inline std::vector<Support> quarter_roof_supports() {
  return {{SupportKind::kHinged, "straight_edges", -1, {}},
          {SupportKind::kSymmetryPlane, "crown", 0, {}},
          {SupportKind::kSymmetryPlane, "axial_midplane", 1, {}}};
}

// Everything a LoadProblem of the roof refers to (it keeps references to mesh and element).
struct SzeRoof {
  Mesh mesh;
  std::vector<Support> supports = quarter_roof_supports();
  Loads loads;
  std::unique_ptr<ShellElement> element = make_shell_element(ElementType::kMitc4);
  ShellLaw law;
  LoadProblemOptions options;
};

// The quarter roof (theta >= 0, y >= 0; isotropic, so symmetric about the crown and the axial
// mid-plane) with n x n mitc4 elements and P/4 at the centre; the centre's downward deflection
// is the monitor "minus_w_center".
inline SzeRoof make_sze_roof(double thickness, int n, int threads = 1) {
  SzeRoof r;
  r.mesh = cylindrical_panel_mesh(kRoofRadius, kRoofLength, kRoofHalfAngleRad * 180 / kPi, n, n,
                                  PanelPart::kQuarter);
  r.loads.points.push_back({"center", Vector3d(0, 0, -kRoofPmax / 4), false});
  r.law = isotropic_shell_law(kRoofE, kRoofNu, thickness);
  r.options.displacements = {{"minus_w_center", "center", -Vector3d::UnitZ()}};
  r.options.threads = threads;
  return r;
}

// Pseudo-arclength from lambda = P/Pmax = 0 to 1.1 (the tables end at 1.08 and 1.03); with
// snap_back the centre deflection's turning points are located too.
inline cont::Settings sze_roof_settings(bool snap_back) {
  cont::Settings settings;
  // Arclength = RMS nodal displacement increment (mm, LoadProblem::inner) and 10 mm per unit
  // load factor: the centre deflects 10-40 mm over the load range.
  settings.parameter_weight = 10;
  settings.step_initial = 0.2;
  settings.step_max = 0.25;         // about 100 points per path, for the linear interpolation
  settings.event_tolerance = 1e-6;  // arclength; the limit load is second order in it
  settings.p_max = 1.1;
  settings.max_steps = 300;
  // ||F||_inf <= 1e-8 of the quarter load Pmax/4: the residual's round-off floor is about
  // 6e-8 N (measured: KINSOL's line search stalls there), 1e-10 of it.
  settings.newton.residual_scale = kRoofPmax / 4;
  settings.newton.relative_tolerance = 1e-8;
  if (snap_back) settings.extremum_monitors = {"minus_w_center"};
  return settings;
}

}  // namespace si::verification
