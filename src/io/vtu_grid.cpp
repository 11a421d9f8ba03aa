#include "io/vtu_grid.hpp"

#include <cmath>

namespace si {
namespace {

// The columns of an array of `kind` that change sign under a reflection of `axis`.
std::vector<int> flipped_columns(FieldKind kind, int axis) {
  switch (kind) {
    case FieldKind::kVector:
      return {axis};
    case FieldKind::kInPlaneTensor:
      return {1};
    case FieldKind::kAlongT1:
      return axis == 0 ? std::vector<int>{0} : std::vector<int>{};
    case FieldKind::kAlongT2:
      return axis == 1 ? std::vector<int>{0} : std::vector<int>{};
    case FieldKind::kScalars:
      break;
  }
  return {};
}

// The rows of `array`, then the rows `copied` of it transformed by the reflection.
VtuArray extended(const VtuArray& array, const std::vector<int>& copied, int axis) {
  VtuArray out{Eigen::MatrixXd(array.values.rows() + static_cast<Eigen::Index>(copied.size()),
                               array.values.cols()),
               array.kind};
  out.values.topRows(array.values.rows()) = array.values;
  for (std::size_t i = 0; i < copied.size(); ++i)
    out.values.row(array.values.rows() + static_cast<Eigen::Index>(i)) =
        array.values.row(copied[i]);
  for (int c : flipped_columns(array.kind, axis))
    out.values.col(c).tail(static_cast<Eigen::Index>(copied.size())) *= -1;
  return out;
}

}  // namespace

VtuGrid mirrored(const VtuGrid& grid, int axis, double tolerance) {
  const Eigen::Index n = grid.points.rows();
  std::vector<int> image(static_cast<std::size_t>(n));  // the mirrored point of each point
  std::vector<int> copied;                              // the points off the plane, in order
  for (Eigen::Index p = 0; p < n; ++p) {
    if (std::abs(grid.points(p, axis)) <= tolerance) {
      image[p] = static_cast<int>(p);
    } else {
      image[p] = static_cast<int>(n + static_cast<Eigen::Index>(copied.size()));
      copied.push_back(static_cast<int>(p));
    }
  }
  VtuGrid out;
  out.points = extended({grid.points, FieldKind::kVector}, copied, axis).values;
  for (const auto& [name, array] : grid.point_data)
    out.point_data[name] = extended(array, copied, axis);
  out.cells = grid.cells;
  std::vector<int> all_cells(grid.cells.size());
  for (std::size_t c = 0; c < grid.cells.size(); ++c) {
    const auto& q = grid.cells[c];
    out.cells.push_back({image[q[0]], image[q[3]], image[q[2]], image[q[1]]});
    all_cells[c] = static_cast<int>(c);
  }
  for (const auto& [name, array] : grid.cell_data)
    out.cell_data[name] = extended(array, all_cells, axis);
  return out;
}

}  // namespace si
