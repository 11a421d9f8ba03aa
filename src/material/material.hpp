// Linear elastic ply material: orthotropic 3-D engineering constants in the material axes
// (1 = fibre, 2 = in-plane transverse, 3 = through-thickness), or isotropic (E, nu).
// Units: moduli in MPa. Poisson's ratios follow the usual convention nu_ij = -eps_j/eps_i for
// stress along i, so nu_ij/E_i = nu_ji/E_j (compliance symmetry).
#pragma once

#include <string>

#include "core/linalg.hpp"
#include "material/ply_strengths.hpp"

namespace si {

struct EngineeringConstants {
  double E1 = 0, E2 = 0, E3 = 0;     // MPa
  double G12 = 0, G13 = 0, G23 = 0;  // MPa
  double nu12 = 0, nu13 = 0, nu23 = 0;
};

class Material {
 public:
  // Both factories validate: every modulus positive, every Poisson ratio within the
  // thermodynamic bound |nu_ij| < sqrt(E_i/E_j), and the compliance matrix positive definite
  // (reported through the determinant 1 - nu12 nu21 - nu23 nu32 - nu13 nu31 - 2 nu21 nu32 nu13).
  // Failures throw an input si::Error whose key names the offending constant.
  static Material orthotropic(std::string name, const EngineeringConstants& c);
  static Material isotropic(std::string name, double E, double nu);

  const std::string& name() const { return name_; }
  const EngineeringConstants& constants() const { return c_; }
  bool is_isotropic() const { return isotropic_; }

  // Strengths and interlaminar toughness (ply_strengths.hpp), empty unless given.
  const PlyStrengths& strengths() const { return strengths_; }
  const FractureToughness& toughness() const { return toughness_; }
  // A copy carrying these failure properties; validates them (input si::Error naming the key).
  Material with_failure_properties(const PlyStrengths& strengths,
                                   const FractureToughness& toughness) const;
  // A copy under another name (a case file's `materials:` key), everything else kept.
  Material renamed(std::string name) const;

  // Compliance and stiffness in material axes, Voigt order [11, 22, 33, 23, 13, 12] with
  // engineering shear strains (vam.md section 1).
  Matrix6d compliance() const;
  Matrix6d stiffness() const;

 private:
  Material(std::string name, const EngineeringConstants& c, bool isotropic);
  std::string name_;
  EngineeringConstants c_;
  bool isotropic_ = false;
  PlyStrengths strengths_;
  FractureToughness toughness_;
};

}  // namespace si
