// VTK XML UnstructuredGrid (.vtu, ASCII) of a shell mesh for ParaView: quads (VTK_QUAD = 9),
// points at the current (x = X + u) or reference positions, point data "displacement" and
// "director" from the nodal state plus any named nodal and element fields.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "model/mesh.hpp"
#include "shell/director.hpp"

namespace si {

struct VtuFields {
  // Name -> values, one row per node (point_data) or element (cell_data); 1, 3 or 6 columns
  // (scalar, vector, 6-vector such as the strain resultants R in Yu order).
  std::map<std::string, Eigen::MatrixXd> point_data;
  std::map<std::string, Eigen::MatrixXd> cell_data;
  bool deformed = true;  // points at X + u (true) or X (false)
};

// Writes `path` atomically (core/atomic_file.hpp). Throws an input error if a field
// has the wrong number of rows or columns or clashes with the built-in names, or the file cannot
// be written.
void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<NodeState>& state,
               const VtuFields& fields = {});

}  // namespace si
