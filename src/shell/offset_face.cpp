#include "shell/offset_face.hpp"

namespace si {

FacePoint face_point(const ElementGeometry& g, double c, const Shape4& L, double weight) {
  FacePoint f{Vector3d::Zero(), Vector3d::Zero(), 0};
  Vector3d P_xi = Vector3d::Zero(), P_eta = Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    const Vector3d Pa = g.X[a] + c * g.D[a];
    f.P += L.N[a] * Pa;
    P_xi += L.N_xi[a] * Pa;
    P_eta += L.N_eta[a] * Pa;
    f.normal += L.N[a] * g.D[a];
  }
  f.normal.normalize();
  f.area = P_xi.cross(P_eta).norm() * weight;
  return f;
}

}  // namespace si
