// What a VTU file holds, before it is encoded: the reference points, the quads and the named
// point and cell arrays with how each transforms under a mirror (io/vtu_writer.hpp writes it).
// A quarter model (mesh.symmetry: quarter, the part x >= 0, y >= 0) is mirrored about x = 0 and
// y = 0 into the full shape for viewing (output.mirror).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/linalg.hpp"

namespace si {

// How an array's columns change under the reflection x -> -x (plane x = 0) or y -> -y:
//  kScalars        every column a scalar (pressure, a failure index at three positions): unchanged;
//  kVector         x, y, z in global axes (displacement, director): the mirrored axis flips;
//  kInPlaneTensor  11, 12, 22 in the local frame t1 = projected x, t2 = n x t1 (N, M, the
//                  membrane strain and the curvature, Yu order): the 12 column flips;
//  kAlongT1        a component along t1 (Q1, shear strain 13): flips under x -> -x;
//  kAlongT2        a component along t2 (Q2, shear strain 23): flips under y -> -y.
// (The frame t1, t2 of a mirrored node is the same construction from the same global x, and the
// director keeps its side, so only the components that pair x with y or a mirrored axis change.)
enum class FieldKind { kScalars, kVector, kInPlaneTensor, kAlongT1, kAlongT2 };

struct VtuArray {
  Eigen::MatrixXd values;  // one row per point or cell
  FieldKind kind = FieldKind::kScalars;
};

struct VtuGrid {
  Eigen::MatrixXd points;  // reference positions, one row per point (mm)
  std::vector<std::array<int, 4>> cells;
  std::map<std::string, VtuArray> point_data;  // written in name order
  std::map<std::string, VtuArray> cell_data;
};

// The grid reflected about the plane x = 0 (axis 0) or y = 0 (axis 1) and joined to itself: the
// points on the plane (|coordinate| <= tolerance) are shared, the others copied with the
// coordinate negated; the copied cells list their nodes in reverse order, so that they keep
// their normals on the side of the directors; the arrays transform by their kind.
VtuGrid mirrored(const VtuGrid& grid, int axis, double tolerance);

}  // namespace si
