// VTK XML UnstructuredGrid (.vtu) of a shell mesh for ParaView: quads (VTK_QUAD = 9), points at
// the reference positions X with the point data "displacement" u and "director" d from the nodal
// state (ParaView's Warp By Vector on "displacement", scale 1, shows the deformed shape X + u),
// plus any named nodal and element fields. Written as text (ascii) or with the arrays appended
// as raw binary (header_type UInt64, the machine's byte order), optionally mirrored from a
// quarter model into the full shape (io/vtu_grid.hpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "io/vtu_grid.hpp"
#include "model/mesh.hpp"
#include "shell/director.hpp"

namespace si {

struct VtuFields {
  // Name -> values, one row per node (point_data) or element (cell_data); 1, 3 or 6 columns
  // (scalar, vector, 6-vector such as the strain resultants R in Yu order).
  std::map<std::string, Eigen::MatrixXd> point_data;
  std::map<std::string, Eigen::MatrixXd> cell_data;
  // How a field transforms under a mirror, by name (default kScalars; only output.mirror reads it).
  std::map<std::string, FieldKind> kinds;
};

// ascii: text, every digit of a double; binary: appended raw data, about a third of the size and
// read without parsing; auto: binary from kBinaryFromPoints points (as written, after a mirror).
enum class VtuEncoding { kAuto, kAscii, kBinary };
constexpr int kBinaryFromPoints = 10000;

struct VtuFormat {
  VtuEncoding encoding = VtuEncoding::kAscii;
  // The mesh is the quarter x >= 0, y >= 0 of a shell symmetric about x = 0 and y = 0: write the
  // full shape (points on a plane within 1e-9 of the mesh's size are shared).
  bool mirror_quarter = false;
};

// Writes `path` atomically (core/atomic_file.hpp). Throws an input error if a field
// has the wrong number of rows or columns or clashes with the built-in names, or the file cannot
// be written.
void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<NodeState>& state,
               const VtuFields& fields = {}, const VtuFormat& format = {});

}  // namespace si
