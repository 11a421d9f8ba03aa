// A face of a shell element offset from its reference surface along the directors, X + c D (the
// contact face, c = the contact offset): its point, unit normal and area element at a point of
// the element, for the contact terms that integrate over it (indentation/interpolated_contact.cpp)
// or weigh their nodes by it (indentation/face_thickening.cpp).
#pragma once

#include "shell/shape4.hpp"
#include "shell/shell_element.hpp"

namespace si {

struct FacePoint {
  Vector3d P;
  Vector3d normal;  // the interpolated directors, normalised
  double area;      // |P_xi x P_eta| times `weight`, mm^2
};

// At the point of the element where the shape functions are L.
FacePoint face_point(const ElementGeometry& g, double c, const Shape4& L, double weight);

}  // namespace si
