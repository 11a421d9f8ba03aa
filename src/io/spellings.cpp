#include "io/spellings.hpp"

namespace si {

const Choices<LocalContactModel>& local_contact_spellings() {
  static const Choices<LocalContactModel> c{{"none", LocalContactModel::kNone},
                                            {"hertz", LocalContactModel::kHertz},
                                            {"yang_sun", LocalContactModel::kYangSun},
                                            {"vam", LocalContactModel::kVam}};
  return c;
}

const Choices<Kinematics>& kinematics_spellings() {
  static const Choices<Kinematics> c{{"linear", Kinematics::kLinear},
                                     {"nonlinear", Kinematics::kNonlinear}};
  return c;
}

}  // namespace si
