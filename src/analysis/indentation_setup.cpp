#include "analysis/indentation_run.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "analysis/local_contact.hpp"
#include "analysis/path_columns.hpp"
#include "analysis/refine_zone.hpp"
#include "contact/indenter_factory.hpp"
#include "core/error.hpp"
#include "model/geometric_imperfection.hpp"
#include "section/vam_section.hpp"

// IndentationSetup: the model (with its imperfection, if the case seeds one), the indenter's pose,
// the contact problem and the damage probe of a case (indentation_run.hpp).
namespace si {
namespace {

// support_frame: the model has a fixture's frame (ShellModel::frame_nodes), whose contact takes
// the Newton paths (run_indentation_path's routing).
IndentationOptions options_of(const IndentationCase& c, int threads,
                              JacobianSolverKind linear_solver, bool support_frame) {
  IndentationOptions o;
  o.linear_solver = linear_solver;
  o.contact_offset = contact_face_offset(c);
  o.frame_offset = back_face_offset(c);
  // Every node the indenter can reach within the path's depth, plus a margin for the shell's
  // own motion towards it; adapt() grows the set if contact still spreads past it.
  o.candidate_depth = 1.2 * c.path.depth_max + 1.0;
  o.ncp = c.contact.solver == ContactSolver::kActiveSet ? NcpFunction::kMin
                                                        : NcpFunction::kFischerBurmeisterMin;
  o.threads = threads;
  // The paper's option (issue #4 item 3); the case file refuses it with nonlinear kinematics.
  o.interpolated_traction = c.contact.traction == ContactTraction::kInterpolated;
  if (c.contact.fbar) {
    const Vector6d fbar_top = analyze_vam(c.laminate).Fbar_top;
    if (o.interpolated_traction) {
      o.interpolated.fbar = true;
      o.interpolated.fbar_top = fbar_top;
    } else {
      o.nodal_fbar = fbar_top;
    }
  }
  o.local = local_contact_law(c);
  if (o.local.kind == LocalLawKind::kElasticFace) {
    // The sphere's chord at the path's depth (a rigid face's contact radius: the shell's own
    // motion only shrinks it), with a margin: the nodes the face couples (elastic_face.hpp).
    // The linear fast path (linear kinematics, no support frame: run_indentation_path) needs no
    // Newton block: -1.
    const double R = c.indenter.radius, d = std::min(c.path.depth_max, R);
    const bool fast = c.kinematics == Kinematics::kLinear && !support_frame;
    o.face_zone_bound = fast ? -1.0 : 1.1 * std::sqrt(d * (2 * R - d)) + 0.5;
  }
  if (c.fixture.type == FixtureType::kAstmD6264Backed && o.local.kind == LocalLawKind::kNone)
    throw_input(
        "a fully backed plate does not bend, and a shell has no through-thickness compliance: "
        "the indenter could not move; give contact.local (hertz, yang_sun, vam, anisotropic)",
        Where{c.file, "fixture.type", "astm_d6264_backed", 0});
  o.monitors = path_monitors(run_columns(monitored_criteria(c)));
  return o;
}

}  // namespace

IndenterPose default_indenter_pose(const IndentationCase& c, const ShellModel& model) {
  IndenterPose pose;
  pose.direction = c.indenter.direction;
  pose.axis = c.indenter.axis;
  const int apex = model.apex_node();
  const IndenterSpec& i = c.indenter;
  const double size = std::max({i.radius, i.a, i.b, i.c, i.length});
  // The reference point (centre or tip) above the apex's contact point by twice the indenter's
  // size: clear of the shell; the first touch is found from there (indenter.hpp).
  const Vector3d top = model.mesh.nodes[apex] + contact_face_offset(c) * model.mesh.directors[apex];
  pose.position = c.indenter.position ? *c.indenter.position
                                      : Vector3d(top - (2 * size + 1.0) * pose.direction);
  return pose;
}

IndentationSetup::IndentationSetup(IndentationCase c, int threads, JacobianSolverKind linear_solver)
    : spec(with_refine_zone(std::move(c))), model(build_shell_model(spec)) {
  if (spec.path.imperfection) {  // before anything reads the mesh's positions
    imperfection = seed_imperfection(spec, threads, linear_solver);
    add_imperfection(model.mesh, imperfection->shape);
    keep_directors_in_symmetry_planes(model.mesh, model.supports);
  }
  pose = default_indenter_pose(spec, model);
  try {
    indenter = make_indenter(spec.indenter, pose);
  } catch (const Error& e) {
    throw e.within(Where{spec.file, "indenter", "", 0});
  }
  try {
    problem = std::make_unique<IndentationProblem>(
        model, *indenter, pose.direction,
        options_of(spec, threads, linear_solver, !model.frame_nodes.empty()));
  } catch (const Error& e) {
    const auto text = [](const Vector3d& v) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "[%g, %g, %g]", v.x(), v.y(), v.z());
      return std::string(buf);
    };
    // The fixture's frame or its contact law; the local law (the elastic face's block).
    if (e.where().key.rfind("fixture", 0) == 0 || e.where().key.rfind("contact.", 0) == 0)
      throw Error(e.kind(), e.reason(), Where{spec.file, e.where().key, e.where().value, 0});
    if (e.where().key == "indenter.direction")  // the direction itself is wrong, not the pose
      throw Error(e.kind(), e.reason(), Where{spec.file, e.where().key, e.where().value, 0});
    if (e.where().key == "element")  // a degenerate element (shell/quad4_shell.cpp)
      throw Error(e.kind(), e.reason(), Where{spec.file, "mesh.element", model.element->name(), 0});
    const std::string where = spec.indenter.position ? "indenter.position" : "indenter";
    const std::string value = text(pose.position) + " mm, direction " + text(pose.direction);
    // The problem names `indenter`; the case's pose is what the user can change.
    throw Error(e.kind(), e.reason(), Where{spec.file, where, value, 0});
  }
  if (spec.damage && !spec.damage->criteria.empty()) {
    damage = std::make_shared<DamageProbe>(model, problem->assembler(), spec.laminate, *spec.damage,
                                           pose.direction, problem->candidates(),
                                           face_pressure_law(spec));
    problem->set_probe(damage);
  }
}

}  // namespace si
