#include "io/default_case.hpp"

namespace si {

std::string default_case_yaml() {
  return "# Built-in default of `shellindent run`: the source paper's cap (docs/case-file.md).\n"
         "material: paper-carbon-epoxy\n"
         "laminate: {layup: \"[0/0]2S\", ply_thickness: 0.475 mm, reference: mid}\n"
         "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
         "mesh: {element: mitc4, size_apex: 0.5 mm, size_edge: 2 mm, refine_radius: 13 mm,\n"
         "       symmetry: quarter}\n"
         "kinematics: nonlinear\n"
         "indenter: {shape: sphere, radius: 12.7 mm}\n"
         "contact: {surface: outer, solver: kinsol}\n"
         "path: {method: pseudo_arclength, depth_max: 10 mm, step: 0.1 mm}\n"
         "output: {dir: results/paper_cap/, vtu_every: 10}\n";
}

}  // namespace si
