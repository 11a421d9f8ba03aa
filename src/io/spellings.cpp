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
                                       {"plate", LocalSupport::kPlate}};
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

}  // namespace si
