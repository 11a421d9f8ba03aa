// A shell model ready for the solvers, built from its spec (the case file's laminate, shell,
// mesh, kinematics and load sections; docs/case-file.md, "How `shellindent static` builds the
// model"): the mesh of `shell` + `mesh`, the VAM section law of
// the laminate, the element, the kinematics, the edge supports and symmetry planes, and the
// loads of the `load` section (no contact).
//
// Conventions:
//  * Every mesh has the node sets "apex" (the load point: the cap's apex, the centre of a plate,
//    the crown centre of a panel, at the origin in plan), "edge" (the supported boundary) and,
//    for a quarter model (x >= 0, y >= 0), "symmetry_x" (x = 0) and "symmetry_y" (y = 0).
//  * The laminate's x1 axis (ply angle 0) is the global x axis projected on the surface at each
//    integration point (ElementGeometry::material_axis = e_x, shell_element.hpp).
//  * The mesh is the laminate's reference surface; the law is the VAM A_R and G about it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/fixture_spec.hpp"
#include "model/load_spec.hpp"
#include "model/loads.hpp"
#include "model/mesh.hpp"
#include "model/mesh_spec.hpp"
#include "model/shell_spec.hpp"
#include "model/supports.hpp"
#include "section/laminate.hpp"
#include "shell/kinematics.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {

// What a shell model is built from. Errors name the spec's `file` and the case-file key.
struct ShellModelSpec {
  Laminate laminate;
  ShellSpec shell;
  MeshSpec mesh;
  Kinematics kinematics = Kinematics::kNonlinear;
  std::optional<LoadSpec> load;  // only for load-controlled runs
  std::string file;              // the file (or label) the spec was read from, for messages
  FixtureSpec fixture;           // a test fixture the plate rests on (none by default)
};

struct ShellModel {
  Mesh mesh;
  ShellLaw law;
  std::unique_ptr<ShellElement> element;
  Kinematics kinematics = Kinematics::kNonlinear;
  std::vector<Support> supports;
  std::vector<PrescribedDisplacement> displacements;  // non-zero ones of `supports:` entries
  Loads loads;  // of the case's `load` section at load factor 1; empty without one
  // Whole-shell value = symmetry_factor * model value, for forces, reactions and energies
  // (4 for a quarter model, else 1).
  double symmetry_factor = 1;
  // The nodes over a fixture's support frame (fixture.hpp; empty: no frame), the candidates of
  // the indentation problem's support-frame contact (indentation/support_frame.hpp).
  std::vector<int> frame_nodes;
  std::vector<std::string> warnings;  // for the user (e.g. the bernstein4 patch-test defect)

  int apex_node() const { return mesh.node_sets.at("apex").front(); }
};

// Throws an input error naming the case-file key for a case the model cannot represent: a
// quarter model of a section that is not specially orthotropic in the model axes
// (`mesh.symmetry`), an odd-sized or too coarse mesh, a simply supported curved edge, a mesh file
// the Gmsh reader refuses, a `supports`/`loads` entry naming a set the mesh does not have.
//
// Named sets of the built-in meshes (docs/case-file.md): "apex", "edge" (the whole supported
// boundary); rectangular plate "x-", "x+", "y-", "y+" (quarter: "x+", "y+"); cylindrical panel
// "x-", "x+" (straight edges), "y-", "y+" (curved ends), "straight_edges", "curved_ends"
// (quarter: "x+", "y+"); cap and circular plate "rim"; quarter models "symmetry_x",
// "symmetry_y". A mesh file brings its physical groups, "apex" and "edge".
ShellModel build_shell_model(const ShellModelSpec& spec);

// The mesh alone (the first step of build_shell_model).
Mesh shell_mesh(const ShellSpec& shell, const MeshSpec& mesh);

// The loads of a `load` section on a mesh built by shell_mesh (node set "apex"); a quarter
// model (symmetry_factor 4) carries a quarter of the apex force.
Loads shell_loads(const LoadSpec& load, double symmetry_factor);

}  // namespace si
