#include "section/reference_surface.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace si {

Matrix6d shift_reference(const Matrix6d& abd_about_mid, double offset_mm) {
  if (!std::isfinite(offset_mm))
    throw_input("reference surface offset must be finite",
                Where{"", "laminate.reference_offset", std::to_string(offset_mm), 0});
  const double e = offset_mm;
  const Matrix3d A = abd_about_mid.topLeftCorner<3, 3>();
  const Matrix3d B = abd_about_mid.topRightCorner<3, 3>();
  const Matrix3d D = abd_about_mid.bottomRightCorner<3, 3>();
  const Matrix3d B_new = B - e * A;
  Matrix6d out;
  out.topLeftCorner<3, 3>() = A;
  out.topRightCorner<3, 3>() = B_new;
  out.bottomLeftCorner<3, 3>() = B_new.transpose();
  out.bottomRightCorner<3, 3>() = D - e * (B + B.transpose()) + e * e * A;
  return out;
}

}  // namespace si
