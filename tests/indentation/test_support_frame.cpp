// The support frame as a second contact body (indentation/support_frame.hpp) and the fixture
// presets (model/fixture.hpp, docs/case-file.md `fixture`): its rows and Jacobian against finite
// differences, equilibrium of the whole plate (indenter force = frame force + clamp reactions, a
// conservation law), complementarity node by node, lift-off where the plate cannot bear, the
// energy bound against the plate clamped on the cut-out's edge (minimum potential energy), and a
// Gmsh file of the same mesh against the built-in one.
#include "indentation/support_frame.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "../model/msh_test_writer.hpp"
#include "analysis/indentation_run.hpp"
#include "analysis/path_columns.hpp"
#include "indentation_test_support.hpp"

namespace si {
namespace {

using testing::exact_solves;
using testing::expect_jacobian_matches_fd;
using testing::IndentationFixture;

// The paper's [0/90]2S carbon/epoxy (t = 3.8 mm) on a fixture, a coarse graded mesh, the D7136
// 16 mm hemispherical impactor as the indenter; `extra` adds YAML lines.
CaseFile fixture_case(const std::string& fixture, const std::string& kinematics = "nonlinear",
                      const std::string& extra = "") {
  const std::string yaml =
      "material: paper-carbon-epoxy\n"
      "laminate: {layup: \"[0/90]2S\", ply_thickness: 0.475 mm, reference: mid}\n"
      "fixture: " +
      fixture +
      "\n"
      "mesh: {size_apex: 3 mm, size_edge: 10 mm, refine_radius: 6 mm}\n"
      "kinematics: " +
      kinematics + "\nindenter: {shape: sphere, radius: 8 mm}\n" + extra;
  return parse_case_file(yaml, "fixture.yaml");
}

const std::string kD7136 = "{type: astm_d7136}";

// ---- the preset's model ----------------------------------------------------------------------

TEST(Fixture, D7136_PlateWindowClampsAndFrameNodes) {
  const CaseFile c = fixture_case(kD7136);
  EXPECT_EQ(c.shell.type, ShellType::kRectangularPlate);
  EXPECT_EQ(c.shell.length_x, 150.0);
  EXPECT_EQ(c.shell.length_y, 100.0);
  EXPECT_TRUE(c.mesh.graded);
  const ShellModel m = build_shell_model(c);
  // Mesh lines on the cut-out's edges: nodes at x = +-62.5 and y = +-37.5.
  int on_x = 0, on_y = 0;
  for (const Vector3d& p : m.mesh.nodes) {
    on_x += std::abs(std::abs(p.x()) - 62.5) < 1e-9;
    on_y += std::abs(std::abs(p.y()) - 37.5) < 1e-9;
  }
  EXPECT_GT(on_x, 0);
  EXPECT_GT(on_y, 0);
  // Every frame node lies outside the open cut-out, every other node inside it.
  std::vector<bool> is_frame(m.mesh.num_nodes(), false);
  for (int n : m.frame_nodes) is_frame[n] = true;
  for (int n = 0; n < m.mesh.num_nodes(); ++n) {
    const Vector3d& p = m.mesh.nodes[n];
    const bool inside = std::abs(p.x()) < 62.5 - 1e-9 && std::abs(p.y()) < 37.5 - 1e-9;
    EXPECT_EQ(is_frame[n], !inside) << n;
  }
  // Four clamps, each the node nearest its tip, holding u_z only; the in-plane rigid-body motion
  // held by the fewest dofs (3), the edges free.
  ASSERT_EQ(m.mesh.node_sets.at("clamps").size(), 4u);
  const std::vector<PrescribedDof> fixed = prescribed_dofs(m.mesh, m.supports, m.displacements);
  int uz = 0, inplane = 0, other = 0;
  for (const PrescribedDof& d : fixed) {
    const int local = d.dof % kShellNodeDofs;
    (local == 2 ? uz : local < 2 ? inplane : other)++;
  }
  EXPECT_EQ(uz, 4);
  EXPECT_EQ(inplane, 3);
  EXPECT_EQ(other, 0);
}

TEST(Fixture, D6264_OpeningAndBacked_FrameNodes) {
  const ShellModel opening =
      build_shell_model(fixture_case("{type: astm_d6264_opening, opening_diameter: 76.2 mm}"));
  for (int n = 0; n < opening.mesh.num_nodes(); ++n) {
    const bool frame = std::find(opening.frame_nodes.begin(), opening.frame_nodes.end(), n) !=
                       opening.frame_nodes.end();
    EXPECT_EQ(frame, opening.mesh.nodes[n].head<2>().norm() >= 38.1 - 1e-6) << n;
  }
  EXPECT_EQ(opening.mesh.node_sets.count("clamps"), 0u);
  const ShellModel backed = build_shell_model(fixture_case("{type: astm_d6264_backed}"));
  EXPECT_EQ(static_cast<int>(backed.frame_nodes.size()), backed.mesh.num_nodes());
}

TEST(Fixture, BadInputNamesTheKey) {
  const auto error_key = [](const std::string& fixture, const std::string& extra = "") {
    try {
      build_shell_model(fixture_case(fixture, "nonlinear", extra));
    } catch (const Error& e) {
      return e.where().key;
    }
    return std::string("(none)");
  };
  EXPECT_EQ(error_key("{type: astm_d7137}"), "fixture.type");
  EXPECT_EQ(error_key("{type: astm_d7136, opening_diameter: 50 mm}"), "fixture.opening_diameter");
  EXPECT_EQ(error_key("{type: astm_d6264_opening}"), "fixture.opening_diameter");
  EXPECT_EQ(error_key("{type: astm_d6264_opening, opening_diameter: 120 mm}"),
            "fixture.opening_diameter");
  EXPECT_EQ(error_key("{type: astm_d7136, window: [160 mm, 75 mm]}"), "fixture.window");
  EXPECT_EQ(error_key("{type: astm_d7136, window: [125 mm]}"), "fixture.window");
  EXPECT_EQ(error_key("{type: astm_d7136, clamps: [[0 mm, 0 mm]]}"), "fixture.clamps");
  EXPECT_EQ(error_key("{type: astm_d7136, clamps: [[90 mm, 40 mm]]}"), "fixture.clamps");
  EXPECT_EQ(error_key(kD7136,
                      "shell: {type: rectangular_plate, length_x: 150 mm, length_y: "
                      "100 mm, edge: clamped}\n"),
            "shell.edge");
  EXPECT_EQ(error_key(kD7136, "shell: {type: flat_circular_plate, radius: 60 mm}\n"), "shell.type");
}

// A fully backed plate cannot bend and a shell has no through-thickness compliance: without a
// local law the indenter could not move, and the run is refused naming the fixture.
TEST(Fixture, D6264Backed_WithoutLocalLaw_IsRefused) {
  std::string key = "(none)";
  try {
    IndentationSetup setup(fixture_case("{type: astm_d6264_backed}"), 1);
  } catch (const Error& e) {
    key = e.where().key;
  }
  EXPECT_EQ(key, "fixture.type");
}

// ---- rows and Jacobian -----------------------------------------------------------------------

// The trial points' multipliers start here (N): away from the NCP function's kink, whose
// curvature would make the central differences' O(eps^2) error exceed the check's 1e-6 (measured:
// the error falls as eps^2, 2.6e-3 at eps 1e-5 to 2.6e-7 at 1e-7, with multipliers from 0).
constexpr double kOffTheKink = 20.0;
// And a smaller central-difference step than the indenter's checks (1e-6): the frame's rows on
// hundreds of nodes near their kink; 1e-7 is still above the roundoff floor (measured ~1e-6 rel.
// at 1e-8).
constexpr double kFrameStep = 1e-7;

// The gap is the back face's height above the frame: a rigid lift of the plate by delta gives
// delta at every frame node, and a turn of the director by theta gives c (cos theta - 1) more.
TEST(SupportFrame, GapIsTheBackFaceHeightAboveTheFrame) {
  IndentationFixture f(fixture_case(kD7136));
  const SupportFrame* frame = f.problem->support_frame();
  ASSERT_NE(frame, nullptr);
  const double c = -1.9;  // back face of the 3.8 mm plate
  std::vector<NodeState> s = f.problem->node_states(f.problem->initial_point());
  for (NodeState& n : s) n.u = Vector3d(0.3, -0.2, 0.25);
  const double theta = 0.1;
  const int turned = frame->candidates().front();
  s[turned].d = Vector3d(std::sin(theta), 0, std::cos(theta));
  const cont::Vector z = f.problem->initial_point();
  const TermPoint p{z, 0.0, s};
  for (int i = 0; i < frame->size(); ++i) {
    const double expected =
        0.25 + (frame->candidates()[i] == turned ? c * (std::cos(theta) - 1) : 0);
    EXPECT_NEAR(frame->gap(i, p, false).gap, expected, 1e-12) << i;
  }
}

// The frame's rows beside the indenter's: the whole Jacobian against central differences at a
// point off the solution with multipliers > 0 on every row (the frame's nonlinear block) and
// gaps of both signs (random shell coordinates).
TEST(SupportFrame, NonlinearJacobianMatchesFiniteDifferences) {
  IndentationFixture f(fixture_case(kD7136), exact_solves());
  ASSERT_GT(f.problem->layout().frame, 0);
  expect_jacobian_matches_fd(*f.problem, 0.3, 0.1, kOffTheKink, kFrameStep);
}

TEST(SupportFrame, LinearJacobianMatchesFiniteDifferences) {
  IndentationFixture f(fixture_case(kD7136, "linear"), exact_solves());
  expect_jacobian_matches_fd(*f.problem, 0.3, 0.1, kOffTheKink, kFrameStep);
}

TEST(SupportFrame, NonlinearJacobianMatchesFiniteDifferences_DirectLu) {
  IndentationOptions o;
  o.linear_solver = JacobianSolverKind::kUmfpack;
  IndentationFixture f(fixture_case("{type: astm_d6264_opening, opening_diameter: 76.2 mm}"), o);
  expect_jacobian_matches_fd(*f.problem, 0.3, 0.1, kOffTheKink, kFrameStep);
}

// The frame does not move with the depth: its rows of dF/dh are zero.
TEST(SupportFrame, DepthDerivativeOfTheFrameRowsIsZero) {
  IndentationFixture f(fixture_case(kD7136));
  const cont::Vector z = testing::trial_point(*f.problem, 3);
  cont::Vector dp;
  ASSERT_TRUE(f.problem->residual_p(z, 0.3, dp));
  const UnknownLayout u = f.problem->layout();
  EXPECT_EQ(dp.segment(u.frame_begin(), u.frame).cwiseAbs().maxCoeff(), 0.0);
}

// ---- paths -----------------------------------------------------------------------------------

PathResult run_path(CaseFile c, double depth_max, double step) {
  c.path.method = PathMethod::kNatural;
  c.path.depth_max = depth_max;
  c.path.step = step;
  c.path.step_min = 1e-4;
  c.path.step_max = step;
  IndentationSetup setup(c, 1);
  PathResult r = run_indentation_path(setup);
  EXPECT_TRUE(r.completed) << r.reason;
  return r;
}

// Complementarity node by node: mu >= 0, g >= 0, mu g = 0 to the solve's tolerance, a reaction
// only where the gap is closed; and the plate's vertical equilibrium.
void expect_frame_kkt(const IndentationState& s) {
  double mu_max = 0;
  for (double mu : s.frame_multipliers) mu_max = std::max(mu_max, mu);
  ASSERT_GT(mu_max, 0);
  for (std::size_t i = 0; i < s.frame_nodes.size(); ++i) {
    const double mu = s.frame_multipliers[i], g = s.frame_gaps[i];
    EXPECT_GT(mu, -1e-8 * mu_max) << s.frame_nodes[i];
    EXPECT_GT(g, -1e-8) << s.frame_nodes[i];
    if (mu > 1e-6 * mu_max) {
      EXPECT_LT(std::abs(g), 1e-8) << s.frame_nodes[i];
    }
  }
  // Indenter force along e = the reactions along -e: the frame's and the clamps'.
  EXPECT_NEAR(s.force, s.reaction, 1e-7 * s.force);
}

// A plate fully backed by a rigid base does not bend: with the Hertz local law in series the
// indenter's whole travel is the local approach, T = k h^1.5, and the frame carries all of it,
// under the indenter only.
TEST(SupportFrame, D6264Backed_HertzLaw_ForceBalance_ReactionsUnderTheIndenterOnly) {
  const CaseFile c =
      fixture_case("{type: astm_d6264_backed}", "nonlinear", "contact: {local: hertz}\n");
  const PathResult r = run_path(c, 0.05, 0.025);
  const IndentationState& s = r.points.back().state;
  expect_frame_kkt(s);
  EXPECT_NEAR(s.frame_force, s.force, 1e-7 * s.force);  // no clamps: the frame holds it alone
  // path.csv's frame_force_N is the state's.
  EXPECT_EQ(column_value(path_column(PathColumn::kFrameForce), r.points.back()), s.frame_force);
  const ShellModel m = build_shell_model(c);
  for (std::size_t i = 0; i < s.frame_nodes.size(); ++i) {
    if (s.frame_multipliers[i] > 1e-6 * s.force) {
      EXPECT_LT(m.mesh.nodes[s.frame_nodes[i]].head<2>().norm(), 8.0) << "reaction off the contact";
    }
  }
  // Hertz: T = 4/3 E* R^1/2 alpha^3/2 with alpha = h (the plate does not move).
  EXPECT_NEAR(s.local_indentation, s.depth, 1e-3 * s.depth);
}

// D7136: the plate bends into the cut-out and bears on its edges; the overhangs beyond them turn
// up about those edges and lift off the frame, most at the middle of the plate's edges, where the
// frame then carries nothing. With the preset's clamps (+-50, +-43.75) the plate's corners stay
// down (measured: 3.4 N at each corner at 1 mm): the overhang twists about the clamps, which hold
// it down. A CalculiX solid model of the same plate bears at the corners too, and agrees on the
// bearing nodes (997 of 1001) and the clamps' share of the force (0.88 / 0.90):
// bench/calculix/d7136_frame.py, docs/theory/contact.md.
TEST(SupportFrame, D7136_OverhangsLiftOff_ReactionsOnlyWhereItBears) {
  const CaseFile c = fixture_case(kD7136);
  const PathResult r = run_path(c, 1.0, 0.25);
  const IndentationState& s = r.points.back().state;
  expect_frame_kkt(s);
  const ShellModel m = build_shell_model(c);
  double mu_max = 0;
  for (double mu : s.frame_multipliers) mu_max = std::max(mu_max, mu);
  const auto at = [&](const Vector3d& p, double x, double y) {
    return std::abs(p.x() - x) < 1e-9 && std::abs(p.y() - y) < 1e-9;
  };
  int lifted = 0, bearing = 0;
  for (std::size_t i = 0; i < s.frame_nodes.size(); ++i) {
    const Vector3d& p = m.mesh.nodes[s.frame_nodes[i]];
    const double g = s.frame_gaps[i], mu = s.frame_multipliers[i];
    // The middle of each edge of the plate: lifted, no reaction.
    if (at(p, 0, 50) || at(p, 0, -50) || at(p, 75, 0) || at(p, -75, 0)) {
      ++lifted;
      EXPECT_GT(g, 0.1) << p.transpose();
      EXPECT_LT(std::abs(mu), 1e-9 * mu_max) << p.transpose();
    }
    // The middle of the cut-out's long edges: bearing.
    if (at(p, 0, 37.5) || at(p, 0, -37.5)) {
      ++bearing;
      EXPECT_GT(mu, 1e-3 * mu_max) << p.transpose();
    }
  }
  EXPECT_EQ(lifted, 4);
  EXPECT_EQ(bearing, 2);
  EXPECT_LT(s.frame_contact_nodes, static_cast<int>(s.frame_nodes.size()) / 2);
}

// Without clamps the plate only rests on the frame, and its corners rise: a plate simply supported
// on a rectangle needs downward corner forces to keep its corners down (Kirchhoff's corner
// reactions, R = 2 D (1 - nu) w_xy; Timoshenko & Woinowsky-Krieger, Theory of Plates, 1959,
// section 31), which a unilateral frame cannot give. So the cut-out's corners and the plate's
// corners lift off and carry nothing, and the frame alone holds the indenter's force. (With the
// preset's clamps, above, the clamps give that hold-down force and the corners stay down: a
// CalculiX solid model on the same plan grid agrees, bench/calculix/d7136_frame.py.)
TEST(SupportFrame, D7136WithoutClamps_CornersLiftOff_FrameHoldsTheForce) {
  const CaseFile c = fixture_case("{type: astm_d7136, clamps: []}", "linear");
  const PathResult r = run_path(c, 0.1, 0.05);
  const IndentationState& s = r.points.back().state;
  expect_frame_kkt(s);
  EXPECT_NEAR(s.frame_force, s.force, 1e-7 * s.force);
  const ShellModel m = build_shell_model(c);
  double mu_max = 0;
  for (double mu : s.frame_multipliers) mu_max = std::max(mu_max, mu);
  int corners = 0;
  for (std::size_t i = 0; i < s.frame_nodes.size(); ++i) {
    const Vector3d& p = m.mesh.nodes[s.frame_nodes[i]];
    const bool plate_corner =
        std::abs(std::abs(p.x()) - 75) < 1e-9 && std::abs(std::abs(p.y()) - 50) < 1e-9;
    const bool cut_out_corner =
        std::abs(std::abs(p.x()) - 62.5) < 1e-9 && std::abs(std::abs(p.y()) - 37.5) < 1e-9;
    if (!plate_corner && !cut_out_corner) continue;
    ++corners;
    EXPECT_GT(s.frame_gaps[i], 1e-3 * s.depth) << p.transpose();
    EXPECT_LT(std::abs(s.frame_multipliers[i]), 1e-9 * mu_max) << p.transpose();
  }
  EXPECT_EQ(corners, 8);
}

// Against the same plate clamped on the cut-out's edge (same mesh, no frame): the clamped
// plate's solution is admissible for the plate on the frame (its overhang stays flat, on the
// frame, u = 0), so by minimum potential energy the frame plate's energy at a depth is at most
// the clamped plate's, and its force lower: lift-off and the edge's free rotation make it softer.
TEST(SupportFrame, D7136_SofterThanThePlateClampedOnTheCutOutEdge) {
  const CaseFile framed = fixture_case(kD7136);
  CaseFile clamped = framed;
  clamped.fixture = FixtureSpec{};
  NamedSupportSpec edge;
  edge.on = "window_edge";
  edge.type = SupportType::kClamped;
  clamped.shell.supports = {edge};
  // The same mesh: its lines on the cut-out's edges, which form the node set window_edge.
  clamped.mesh.line_x = 62.5;
  clamped.mesh.line_y = 37.5;
  const PathResult a = run_path(framed, 1.0, 0.25);
  const PathResult b = run_path(clamped, 1.0, 0.25);
  // Natural steps land on the grid 0.25, 0.5, ... (a halved step adds points between).
  int compared = 0;
  for (const PathPoint& pa : a.points)
    for (const PathPoint& pb : b.points) {
      const IndentationState &sa = pa.state, &sb = pb.state;
      if (sa.depth == 0 || std::abs(sa.depth - sb.depth) > 1e-12) continue;
      ++compared;
      EXPECT_LE(sa.energy, sb.energy * (1 + 1e-9)) << sa.depth;
      EXPECT_LT(sa.force, sb.force) << sa.depth;
      std::printf("[ fixture  ] h = %.2f mm: frame %.1f N, clamped edge %.1f N (ratio %.3f)\n",
                  sa.depth, sa.force, sb.force, sa.force / sb.force);
    }
  EXPECT_GE(compared, 4);
}

// The same plate from a Gmsh file (the built-in mesh written as MSH 4.1, the frame and clamps
// found by position again) gives the same path to 0.5 %.
TEST(Fixture, D7136_GmshFileOfTheSameMesh_SamePath) {
  const CaseFile builtin = fixture_case(kD7136);
  const ShellModel m = build_shell_model(builtin);
  const std::string file =
      (std::filesystem::temp_directory_path() / "shellindent_d7136_plate.msh").string();
  testing::write_msh41(m.mesh, {}, file);
  CaseFile imported = builtin;
  imported.mesh.file = file;
  const PathResult a = run_path(builtin, 1.0, 0.25);
  const PathResult b = run_path(imported, 1.0, 0.25);
  std::filesystem::remove(file);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 1; k < a.points.size(); ++k)
    EXPECT_NEAR(b.points[k].state.force, a.points[k].state.force, 5e-3 * a.points[k].state.force)
        << a.points[k].state.depth;
}

}  // namespace
}  // namespace si
