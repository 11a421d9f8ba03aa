#include "io/spellings.hpp"

namespace si {

const Choices<LocalContactModel>& local_contact_spellings() {
  static const Choices<LocalContactModel> c{{"none", LocalContactModel::kNone},
                                            {"hertz", LocalContactModel::kHertz},
                                            {"yang_sun", LocalContactModel::kYangSun},
                                            {"vam", LocalContactModel::kVam},
                                            {"anisotropic", LocalContactModel::kAnisotropic}};
  return c;
}

const Choices<LocalSupport>& local_support_spellings() {
  static const Choices<LocalSupport> c{{"half_space", LocalSupport::kHalfSpace},
                                       {"bonded", LocalSupport::kBondedBase},
                                       {"frictionless", LocalSupport::kFrictionlessBase},
                                       {"plate", LocalSupport::kPlate},
                                       {"shell", LocalSupport::kShell}};
  return c;
}

const Choices<LocalPlies>& local_plies_spellings() {
  static const Choices<LocalPlies> c{{"homogenised", LocalPlies::kHomogenised},
                                     {"resolved", LocalPlies::kResolved}};
  return c;
}

const Choices<Kinematics>& kinematics_spellings() {
  static const Choices<Kinematics> c{{"linear", Kinematics::kLinear},
                                     {"nonlinear", Kinematics::kNonlinear}};
  return c;
}

const Choices<bool>& boolean_spellings() {
  static const Choices<bool> c{{"false", false}, {"true", true}};
  return c;
}

const Choices<PathMethod>& path_method_spellings() {
  static const Choices<PathMethod> c{{"natural", PathMethod::kNatural},
                                     {"pseudo_arclength", PathMethod::kPseudoArclength}};
  return c;
}

const Choices<Criterion>& criterion_spellings() {
  static const Choices<Criterion> c{{"max_stress", Criterion::kMaxStress},
                                    {"tsai_wu", Criterion::kTsaiWu},
                                    {"hashin", Criterion::kHashin},
                                    {"delamination", Criterion::kQuadraticDelamination}};
  return c;
}

const Choices<StressRecovery>& recovery_spellings() {
  static const Choices<StressRecovery> c{{"first_order", StressRecovery::kFirstOrder},
                                         {"refined", StressRecovery::kRefined}};
  return c;
}

const Choices<FacePressure>& face_pressure_spellings() {
  static const Choices<FacePressure> c{{"hertz", FacePressure::kHertz},
                                       {"nodal", FacePressure::kNodal}};
  return c;
}

const Choices<EffectiveBendingStiffness>& bending_stiffness_spellings() {
  static const Choices<EffectiveBendingStiffness> c{
      {"olsson", EffectiveBendingStiffness::kOlsson},
      {"geometric_mean", EffectiveBendingStiffness::kGeometricMean}};
  return c;
}

const Choices<FailureMode>& failure_mode_spellings() {
  using M = FailureMode;
  static const Choices<M> c{{"none", M::kNone},
                            {"fibre_tension", M::kFibreTension},
                            {"fibre_compression", M::kFibreCompression},
                            {"matrix_tension", M::kMatrixTension},
                            {"matrix_compression", M::kMatrixCompression},
                            {"normal_tension", M::kNormalTension},
                            {"normal_compression", M::kNormalCompression},
                            {"shear_12", M::kShear12},
                            {"shear_13", M::kShear13},
                            {"shear_23", M::kShear23},
                            {"delamination", M::kDelamination}};
  return c;
}

const Choices<PlyPosition>& ply_position_spellings() {
  static const Choices<PlyPosition> c{{"bottom", PlyPosition::kBottom},
                                      {"middle", PlyPosition::kMiddle},
                                      {"top", PlyPosition::kTop}};
  return c;
}

const Choices<EnergyOutcome>& energy_outcome_spellings() {
  static const Choices<EnergyOutcome> c{{"reached", EnergyOutcome::kReached},
                                        {"beyond_path", EnergyOutcome::kBeyondPath}};
  return c;
}

}  // namespace si
